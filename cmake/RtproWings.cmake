# Wings: a module split into folders src/MODULE/WING/, each a library rtpro_MODULE_WING of its own,
# declared in the order the data flows. A wing sees the module's public headers
# (include/rtpro/MODULE/, through rtpro_MODULE_headers), its own headers, and only the headers a
# wing below it SHARES; it may use only wings declared before it, so the arrows point one way.
# Other modules see only the public headers.

# rtpro_add_wing(MODULE WING [SHARES header...] [USES wing...] [PRIVATE_DEPENDS target...])
# SHARES are the wing's headers the wings above may include (names, or patterns such as *_bsdf.h
# for a family of kinds whose registry is shared, so a new kind's header needs no entry): each is
# linked into an include root of the wing's own, so its other headers stay private to it. A shared
# header may include only public headers and other shared ones.
function(rtpro_add_wing module wing)
  cmake_parse_arguments(ARG "" "" "SHARES;USES;PRIVATE_DEPENDS" ${ARGN})
  set(folder ${CMAKE_SOURCE_DIR}/src/${module}/${wing})
  set(shared_root ${CMAKE_BINARY_DIR}/wing_include/${module}/${wing})
  file(REMOVE_RECURSE ${shared_root})
  file(MAKE_DIRECTORY ${shared_root})
  foreach(pattern IN LISTS ARG_SHARES)
    file(GLOB headers CONFIGURE_DEPENDS RELATIVE ${folder} ${folder}/${pattern})
    if(NOT headers)
      message(FATAL_ERROR "${module} wing ${wing} shares ${pattern}, which is not in src/${module}/${wing}/")
    endif()
    foreach(header IN LISTS headers)
      file(CREATE_LINK ${folder}/${header} ${shared_root}/${header} SYMBOLIC)
    endforeach()
  endforeach()

  set(target rtpro_${module}_${wing})
  file(GLOB sources CONFIGURE_DEPENDS ${folder}/*.cpp)
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} PUBLIC ${shared_root} PRIVATE ${folder})
  target_link_libraries(${target} PUBLIC rtpro_${module}_headers)
  foreach(below IN LISTS ARG_USES)
    if(NOT TARGET rtpro_${module}_${below})
      message(FATAL_ERROR "${module} wing ${wing} uses ${below}, which is not a wing below it")
    endif()
    target_link_libraries(${target} PRIVATE rtpro_${module}_${below})
  endforeach()
  target_link_libraries(${target} PRIVATE ${ARG_PRIVATE_DEPENDS})
  set_property(GLOBAL APPEND PROPERTY RTPRO_${module}_WINGS ${wing})
endfunction()

# rtpro_module_wings(MODULE OUT_VAR): the wings of MODULE declared so far, bottom first.
function(rtpro_module_wings module out_var)
  get_property(wings GLOBAL PROPERTY RTPRO_${module}_WINGS)
  set(${out_var} ${wings} PARENT_SCOPE)
endfunction()
