# scene: four wings (RtproWings.cmake), in the order the data flows: mesh (OBJ/MTL, PLY,
# triangulation, normals, the mesh type) <- gltf (glTF assets) <- yaml (scene files: the YAML
# document, includes, variables, keyframes, the readers, and a glTF file read as a scene) and build
# (description -> render scene, cost estimates, range checks). rtpro_scene, what the other modules
# link, is all four wings behind the public headers.

rtpro_module_include_root(scene scene_root)
add_library(rtpro_scene_headers INTERFACE)
target_include_directories(rtpro_scene_headers INTERFACE ${scene_root})
target_link_libraries(rtpro_scene_headers INTERFACE rtpro_core rtpro_volume)

# OpenSubdiv (Debian's libosd-dev): its CMake config also names static libraries Debian does not
# ship, so find_package(OpenSubdiv) fails; the CPU library (Far, Sdc, Vtr) is found directly and the
# GPU one never linked. Only src/scene/mesh/subdivision_refine.cpp includes it.
find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/far/topologyRefiner.h REQUIRED)
find_library(OPENSUBDIV_CPU_LIBRARY osdCPU REQUIRED)
add_library(rtpro_opensubdiv INTERFACE IMPORTED)
target_include_directories(rtpro_opensubdiv SYSTEM INTERFACE ${OPENSUBDIV_INCLUDE_DIR})
target_link_libraries(rtpro_opensubdiv INTERFACE ${OPENSUBDIV_CPU_LIBRARY})

rtpro_add_wing(scene mesh
  SHARES ascii_scan.h cage_check.h hair_file.h mapped_file.h mesh_limits.h mesh_normals.h
         mtl_parser.h path_containment.h subdivision_refine.h
  PRIVATE_DEPENDS TBB::tbb rtpro_opensubdiv)
rtpro_add_wing(scene gltf
  SHARES gltf_animation.h gltf_asset.h gltf_deformation.h gltf_loader.h gltf_morph.h gltf_motion.h gltf_pose.h gltf_quaternion.h gltf_skin.h
  USES mesh PRIVATE_DEPENDS TinyGLTF::TinyGLTF)
rtpro_add_wing(scene yaml USES gltf mesh PRIVATE_DEPENDS PkgConfig::libyaml)
rtpro_add_wing(scene build USES gltf mesh)

# The wings' headers stay theirs: a module that links rtpro_scene sees only the public headers.
add_library(rtpro_scene INTERFACE)
target_link_libraries(rtpro_scene INTERFACE rtpro_scene_headers)
rtpro_module_wings(scene scene_wings)
foreach(wing IN LISTS scene_wings)
  target_link_libraries(rtpro_scene INTERFACE $<LINK_ONLY:rtpro_scene_${wing}>)
endforeach()

# OpenSubdiv's headers are compiled in the one file that includes them, not in a batch of others.
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/scene/mesh/subdivision_refine.cpp
                            PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
