# scene: four wings, each a folder src/scene/WING/ and a library rtpro_scene_WING, in the order the
# data flows: mesh (OBJ/MTL, PLY, triangulation, normals, the mesh type) <- gltf (glTF assets) <-
# yaml (scene files: the YAML document, includes, variables, keyframes, the readers, and a glTF
# file read as a scene) and build (description -> render scene, cost estimates, range checks).
# A wing sees the public headers in include/rtpro/scene/, its own headers, and only the headers a
# wing below it SHARES; a wing may use only wings declared before it, so the arrows point one way.
# rtpro_scene, what the other modules link, is all four wings behind the public headers.

rtpro_module_include_root(scene scene_root)
add_library(rtpro_scene_headers INTERFACE)
target_include_directories(rtpro_scene_headers INTERFACE ${scene_root})
target_link_libraries(rtpro_scene_headers INTERFACE rtpro_core)

# rtpro_add_scene_wing(WING [SHARES header...] [USES wing...] [PRIVATE_DEPENDS target...])
# SHARES are the wing's headers the wings above may include: each is linked into an include root
# of the wing's own, so its other headers stay private to it.
function(rtpro_add_scene_wing wing)
  cmake_parse_arguments(ARG "" "" "SHARES;USES;PRIVATE_DEPENDS" ${ARGN})
  set(folder ${CMAKE_SOURCE_DIR}/src/scene/${wing})
  set(shared_root ${CMAKE_BINARY_DIR}/scene_wing_include/${wing})
  file(REMOVE_RECURSE ${shared_root})
  file(MAKE_DIRECTORY ${shared_root})
  foreach(header IN LISTS ARG_SHARES)
    if(NOT EXISTS ${folder}/${header})
      message(FATAL_ERROR "scene wing ${wing} shares ${header}, which is not in src/scene/${wing}/")
    endif()
    file(CREATE_LINK ${folder}/${header} ${shared_root}/${header} SYMBOLIC)
  endforeach()

  set(target rtpro_scene_${wing})
  file(GLOB sources CONFIGURE_DEPENDS ${folder}/*.cpp)
  add_library(${target} STATIC ${sources})
  target_include_directories(${target} PUBLIC ${shared_root} PRIVATE ${folder})
  target_link_libraries(${target} PUBLIC rtpro_scene_headers)
  foreach(below IN LISTS ARG_USES)
    if(NOT TARGET rtpro_scene_${below})
      message(FATAL_ERROR "scene wing ${wing} uses ${below}, which is not a wing below it")
    endif()
    target_link_libraries(${target} PRIVATE rtpro_scene_${below})
  endforeach()
  target_link_libraries(${target} PRIVATE ${ARG_PRIVATE_DEPENDS})
  set_property(GLOBAL APPEND PROPERTY RTPRO_SCENE_WINGS ${wing})
endfunction()

rtpro_add_scene_wing(mesh
  SHARES ascii_scan.h large_buffer.h mapped_file.h mesh_limits.h mesh_normals.h mtl_parser.h path_containment.h
  PRIVATE_DEPENDS TBB::tbb)
rtpro_add_scene_wing(gltf SHARES gltf_asset.h gltf_loader.h USES mesh PRIVATE_DEPENDS TinyGLTF::TinyGLTF)
rtpro_add_scene_wing(yaml USES gltf mesh PRIVATE_DEPENDS PkgConfig::libyaml)
rtpro_add_scene_wing(build USES gltf mesh)

# The wings' headers stay theirs: a module that links rtpro_scene sees only the public headers.
add_library(rtpro_scene INTERFACE)
target_link_libraries(rtpro_scene INTERFACE rtpro_scene_headers)
get_property(scene_wings GLOBAL PROPERTY RTPRO_SCENE_WINGS)
foreach(wing IN LISTS scene_wings)
  target_link_libraries(rtpro_scene INTERFACE $<LINK_ONLY:rtpro_scene_${wing}>)
endforeach()
