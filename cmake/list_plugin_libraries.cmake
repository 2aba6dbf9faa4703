# Writes the shared libraries the image plugin loads, one soname a line, deepest first (the reverse
# of ldd's breadth-first load order), to OUTPUT; an empty file when ldd cannot tell. The image
# layer's loader opens them one by one before the plugin (src/image/image_layer.cpp says why).
#   cmake -DPLUGIN=librtpro_image_oiio.so -DOUTPUT=librtpro_image_oiio.so.libraries -P list_plugin_libraries.cmake
execute_process(COMMAND ldd "${PLUGIN}" OUTPUT_VARIABLE text RESULT_VARIABLE status ERROR_QUIET)
set(sonames "")
if(status EQUAL 0)
  string(REPLACE "\n" ";" lines "${text}")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[ \t]*([^ \t]+) => /")
      list(APPEND sonames "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  list(REVERSE sonames)
endif()
list(JOIN sonames "\n" content)
file(WRITE "${OUTPUT}.tmp" "${content}\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
