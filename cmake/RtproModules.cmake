# rtpro_add_module(NAME [DEPENDS module...] [PRIVATE_DEPENDS target-or-module...]
#                  [EXTRA_SOURCES file...] [EXCLUDE file-name...])
#
# Builds src/NAME/*.cpp into the library rtpro_NAME (an interface library when there are no
# sources). Its public headers are include/rtpro/NAME/; headers only the module uses sit beside
# its sources in src/NAME/. Every module gets an include root of its own that holds just
# rtpro/NAME (a link into include/), so a source file can include the public headers of its own
# module and of the modules it links, and nothing else: an include against the data flow is a
# compile error, not a convention. DEPENDS modules are public (their types appear in this module's
# headers); PRIVATE_DEPENDS are used only inside the sources. Names in either list that are not
# rtpro modules are passed through as ordinary targets.
function(rtpro_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS;PRIVATE_DEPENDS;EXTRA_SOURCES;EXCLUDE" ${ARGN})
  rtpro_module_include_root(${name} root)

  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${name}/*.cpp)
  foreach(excluded IN LISTS ARG_EXCLUDE)
    list(FILTER sources EXCLUDE REGEX ".*/src/${name}/${excluded}$")
  endforeach()
  list(APPEND sources ${ARG_EXTRA_SOURCES})

  set(target rtpro_${name})
  if(sources)
    add_library(${target} STATIC ${sources})
    set(scope PUBLIC)
    target_include_directories(${target} PUBLIC ${root} PRIVATE ${CMAKE_SOURCE_DIR}/src/${name})
    target_compile_definitions(${target} PRIVATE RTPRO_VERSION="${PROJECT_VERSION}")
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
    target_include_directories(${target} INTERFACE ${root})
  endif()

  foreach(dep IN LISTS ARG_DEPENDS)
    if(TARGET rtpro_${dep})
      target_link_libraries(${target} ${scope} rtpro_${dep})
    else()
      target_link_libraries(${target} ${scope} ${dep})
    endif()
  endforeach()
  foreach(dep IN LISTS ARG_PRIVATE_DEPENDS)
    if(TARGET rtpro_${dep})
      set(dep rtpro_${dep})
    endif()
    if(scope STREQUAL "INTERFACE")
      target_link_libraries(${target} INTERFACE ${dep})
    else()
      target_link_libraries(${target} PRIVATE ${dep})
    endif()
  endforeach()
endfunction()

# rtpro_module_include_root(NAME OUT_VAR): the include root that holds just rtpro/NAME, for the
# module's library and for any other library that stands in for part of it (see
# RtproImageLayer.cmake).
function(rtpro_module_include_root name out_var)
  set(root ${CMAKE_BINARY_DIR}/module_include/${name})
  file(MAKE_DIRECTORY ${root}/rtpro)
  if(NOT EXISTS ${root}/rtpro/${name} AND EXISTS ${CMAKE_SOURCE_DIR}/include/rtpro/${name})
    file(CREATE_LINK ${CMAKE_SOURCE_DIR}/include/rtpro/${name} ${root}/rtpro/${name} SYMBOLIC)
  endif()
  set(${out_var} ${root} PARENT_SCOPE)
endfunction()
