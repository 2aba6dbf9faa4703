# Wings: a module split into folders src/MODULE/WING/, each a library rtpro_MODULE_WING of its own,
# declared in the order the data flows. A wing sees the module's public headers
# (include/rtpro/MODULE/, through rtpro_MODULE_headers), its own headers, and only the headers a
# wing below it SHARES; it may use only wings declared before it, so the arrows point one way.
# Other modules see only the public headers.

# rtpro_add_wing(MODULE WING [SHARES header...] [SHARES_MATCHING pattern...] [USES wing...]
#                [PRIVATE_DEPENDS target...])
# SHARES are the wing's headers the wings above may include: each is linked into an include root
# of the wing's own, so its other headers stay private to it. A shared header may include only
# public headers and other shared ones. SHARES_MATCHING shares every header whose name matches a
# pattern: each kind's header (`*_light_sample.h`), which a shared registry includes, so that a new
# kind's header is shared as it appears (the build re-runs CMake) and adding a kind edits no list.
function(rtpro_add_wing module wing)
  cmake_parse_arguments(ARG "" "" "SHARES;SHARES_MATCHING;USES;PRIVATE_DEPENDS" ${ARGN})
  set(folder ${CMAKE_SOURCE_DIR}/src/${module}/${wing})
  foreach(pattern IN LISTS ARG_SHARES_MATCHING)
    file(GLOB matching RELATIVE ${folder} CONFIGURE_DEPENDS ${folder}/${pattern})
    list(APPEND ARG_SHARES ${matching})
  endforeach()
  set(shared_root ${CMAKE_BINARY_DIR}/wing_include/${module}/${wing})
  file(REMOVE_RECURSE ${shared_root})
  file(MAKE_DIRECTORY ${shared_root})
  foreach(header IN LISTS ARG_SHARES)
    if(NOT EXISTS ${folder}/${header})
      message(FATAL_ERROR "${module} wing ${wing} shares ${header}, which is not in src/${module}/${wing}/")
    endif()
    file(CREATE_LINK ${folder}/${header} ${shared_root}/${header} SYMBOLIC)
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
