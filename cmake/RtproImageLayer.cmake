# The image module (src/image, include/rtpro/image) as four libraries, so that the rtpro executable
# does not load OpenImageIO's ~260 shared libraries (half a second, 120 MB) unless it reads or
# writes an image. See include/rtpro/image/image_layer.h.
#
#   rtpro_image_common   output checks, pixel encodings, OpenColorIO colour configs, the EXR
#                        writer and reader (OpenEXR, libdeflate) and the PNG writer (libpng): no
#                        OpenImageIO (the output check uses a list generated from it at build time)
#   rtpro_image          the whole module, calling OpenImageIO directly: what tests link
#   rtpro_image_oiio     librtpro_image_oiio.so, rtpro_image as a plugin beside the executable
#   rtpro_image_loader   the executable's stand-in for rtpro_image: loads the plugin and forwards
#   rtpro_image_headers  just the headers, for modules that only use the Image type (render)

rtpro_module_include_root(image image_root)
set(image_src ${CMAKE_SOURCE_DIR}/src/image)

# The bundled OpenColorIO config is compiled into the binary so rtpro works from any folder.
file(READ ${image_src}/rtpro_config.ocio RTPRO_BUNDLED_OCIO_CONFIG)
configure_file(${image_src}/bundled_ocio_config.cpp.in ${CMAKE_BINARY_DIR}/generated/bundled_ocio_config.cpp @ONLY)

# What OpenImageIO can write, asked of OpenImageIO itself when rtpro is built.
add_executable(rtpro_generate_oiio_output_formats ${image_src}/generate_oiio_output_formats.cpp)
target_link_libraries(rtpro_generate_oiio_output_formats PRIVATE OpenImageIO::OpenImageIO)
add_custom_command(
  OUTPUT ${CMAKE_BINARY_DIR}/generated/oiio_output_formats.cpp
  COMMAND rtpro_generate_oiio_output_formats ${CMAKE_BINARY_DIR}/generated/oiio_output_formats.cpp
  DEPENDS rtpro_generate_oiio_output_formats
  COMMENT "Listing the output formats OpenImageIO can write")

set(image_common_sources atomic_file_replacement.cpp color_config.cpp direct_output.cpp display_encoding.cpp
                         exr_input.cpp exr_output.cpp exr_zip_block.cpp image_file_check.cpp
                         image_header_check.cpp image_metadata.cpp image_read_limits.cpp output_check.cpp pixel_encoding.cpp png_output.cpp)
set(image_loader_sources image_layer.cpp)
set(image_plugin_sources image_plugin.cpp)
set(image_tool_sources generate_oiio_output_formats.cpp)

add_library(rtpro_image_headers INTERFACE)
target_include_directories(rtpro_image_headers INTERFACE ${image_root})
target_link_libraries(rtpro_image_headers INTERFACE rtpro_core)

list(TRANSFORM image_common_sources PREPEND ${image_src}/ OUTPUT_VARIABLE common_files)
add_library(rtpro_image_common STATIC ${common_files} ${CMAKE_BINARY_DIR}/generated/bundled_ocio_config.cpp
            ${CMAKE_BINARY_DIR}/generated/oiio_output_formats.cpp)
target_include_directories(rtpro_image_common PUBLIC ${image_root} PRIVATE ${image_src})
target_compile_definitions(rtpro_image_common PRIVATE RTPRO_VERSION="${PROJECT_VERSION}")
target_link_libraries(rtpro_image_common PUBLIC rtpro_core PRIVATE PkgConfig::OpenColorIO OpenEXR::OpenEXR
                      PkgConfig::libdeflate PNG::PNG TBB::tbb)

rtpro_add_module(image DEPENDS core image_common PRIVATE_DEPENDS OpenImageIO::OpenImageIO
                 EXCLUDE ${image_common_sources} ${image_loader_sources} ${image_plugin_sources}
                         ${image_tool_sources})

# The loader defines the same functions as rtpro_image (and image_layer_linked.cpp the loader's
# own, for programs without it): a program links one or the other. The executable links the
# loader, the tests and the plugin link rtpro_image, and the modules between them (rtpro_cli) only
# the headers and rtpro_image_common.

# The plugin holds its own copies of rtpro_image and everything it links; --exclude-libs keeps
# them local, so only the entry point (image_plugin.cpp) is exported.
set_target_properties(rtpro_core rtpro_image_common rtpro_image PROPERTIES POSITION_INDEPENDENT_CODE ON)
add_library(rtpro_image_oiio MODULE ${image_src}/image_plugin.cpp)
target_include_directories(rtpro_image_oiio PRIVATE ${image_src})
target_compile_definitions(rtpro_image_oiio PRIVATE RTPRO_VERSION="${PROJECT_VERSION}")
target_link_libraries(rtpro_image_oiio PRIVATE rtpro_image)
target_link_options(rtpro_image_oiio PRIVATE -Wl,--exclude-libs,ALL)
# Every symbol resolved inside the plugin, except in a sanitizer build: there the sanitizer
# runtimes live in the executable that loads it.
if(NOT RTPRO_SANITIZE)
  target_link_options(rtpro_image_oiio PRIVATE -Wl,--no-undefined)
endif()
set_target_properties(rtpro_image_oiio PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
# The libraries the plugin pulls in, deepest first, for the loader to open one by one before it.
add_custom_command(TARGET rtpro_image_oiio POST_BUILD
                   COMMAND ${CMAKE_COMMAND} -DPLUGIN=$<TARGET_FILE:rtpro_image_oiio>
                           -DOUTPUT=$<TARGET_FILE:rtpro_image_oiio>.libraries
                           -P ${CMAKE_CURRENT_LIST_DIR}/list_plugin_libraries.cmake
                   VERBATIM)

add_library(rtpro_image_loader STATIC ${image_src}/image_layer.cpp)
target_include_directories(rtpro_image_loader PRIVATE ${image_src})
target_compile_definitions(rtpro_image_loader PRIVATE RTPRO_VERSION="${PROJECT_VERSION}")
target_link_libraries(rtpro_image_loader PUBLIC rtpro_image_common PRIVATE ${CMAKE_DL_LIBS} Threads::Threads)
# Whoever links the loader needs the plugin built beside the executable.
add_dependencies(rtpro_image_loader rtpro_image_oiio)
