# scene: four wings (RtproWings.cmake), in the order the data flows: mesh (OBJ/MTL, PLY,
# triangulation, normals, the mesh type) <- gltf (glTF assets) <- yaml (scene files: the YAML
# document, includes, variables, keyframes, the readers, and a glTF file read as a scene) and build
# (description -> render scene, cost estimates, range checks). rtpro_scene, what the other modules
# link, is all four wings behind the public headers.

rtpro_module_include_root(scene scene_root)
add_library(rtpro_scene_headers INTERFACE)
target_include_directories(rtpro_scene_headers INTERFACE ${scene_root})
target_link_libraries(rtpro_scene_headers INTERFACE rtpro_core rtpro_volume)

rtpro_add_wing(scene mesh
  SHARES ascii_scan.h large_buffer.h mapped_file.h mesh_limits.h mesh_normals.h mtl_parser.h path_containment.h
  PRIVATE_DEPENDS TBB::tbb)
rtpro_add_wing(scene gltf SHARES gltf_asset.h gltf_loader.h USES mesh PRIVATE_DEPENDS TinyGLTF::TinyGLTF)
rtpro_add_wing(scene yaml USES gltf mesh PRIVATE_DEPENDS PkgConfig::libyaml)
rtpro_add_wing(scene build USES gltf mesh)

# The wings' headers stay theirs: a module that links rtpro_scene sees only the public headers.
add_library(rtpro_scene INTERFACE)
target_link_libraries(rtpro_scene INTERFACE rtpro_scene_headers)
rtpro_module_wings(scene scene_wings)
foreach(wing IN LISTS scene_wings)
  target_link_libraries(rtpro_scene INTERFACE $<LINK_ONLY:rtpro_scene_${wing}>)
endforeach()
