# render: seven wings (RtproWings.cmake), in the order the data flows: sampling (the samplers, every
# random number's one source; alias tables) and surface (hit -> surface point, textures, normal
# maps) <- bsdf (the BSDF kinds, microfacet tables), lights (light kinds, sampling, the tree,
# linking) and media (medium kinds, phase function, tracking) <- film (pixel sums, passes, adaptive sampling, tiles) <- integrators (whitted, path).
# rtpro_render itself is the renderer on top of them (src/render/*.cpp: camera, tile renderer,
# passes over tiles) behind the public headers, which are all that other modules see.

rtpro_module_include_root(render render_root)
add_library(rtpro_render_headers INTERFACE)
target_include_directories(rtpro_render_headers INTERFACE ${render_root})
target_link_libraries(rtpro_render_headers INTERFACE rtpro_backend rtpro_image_headers)

rtpro_add_wing(render sampling SHARES alias_table.h camera_samplers.h sample_dimensions.h sobol_sampler.h)
rtpro_add_wing(render surface
  SHARES film_motion.h hit_prefetch.h normal_map.h ray_offset.h shading_frame.h surface.h surface_batch.h texture.h)
rtpro_add_wing(render bsdf
  SHARES bsdf.h bsdf_from.h bsdf_sample.h cosine_lanes.h dielectric.h hair_lobes.h microfacet.h sheen.h
  SHARES_MATCHING *_bsdf.h
  USES surface
  PRIVATE_DEPENDS TBB::tbb)
rtpro_add_wing(render lights
  SHARES light_linking.h light_picker.h light_sample.h light_sample_value.h light_set.h light_tree.h path_light.h
         point_light_lanes.h
  SHARES_MATCHING *_light_sample.h
  USES sampling surface
  PRIVATE_DEPENDS TBB::tbb)
rtpro_add_wing(render media
  SHARES beer_lambert.h hg_phase.h medium.h medium_interface.h medium_stack.h medium_tracking.h
  SHARES_MATCHING *_medium.h
  USES surface)
rtpro_add_wing(render film PRIVATE_DEPENDS TBB::tbb)
rtpro_add_wing(render integrators
  SHARES camera_batch.h integrator.h path_integrator.h vertex_samples.h whitted_integrator.h
  USES sampling surface bsdf lights media film)
# Each defines members of PathVertexStep and instantiates them for both template arguments: in one
# unity file with path_vertex_step.cpp, whose `template class` instantiates every member already
# defined, clang rejects the second instantiation.
set_source_files_properties(${CMAKE_SOURCE_DIR}/src/render/integrators/path_medium_step.cpp
                            ${CMAKE_SOURCE_DIR}/src/render/integrators/path_subsurface_step.cpp
                            PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)

file(GLOB render_sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/render/*.cpp)
add_library(rtpro_render STATIC ${render_sources})
target_link_libraries(rtpro_render PUBLIC rtpro_render_headers PRIVATE TBB::tbb)
rtpro_module_wings(render render_wings)
foreach(wing IN LISTS render_wings)
  target_link_libraries(rtpro_render PRIVATE rtpro_render_${wing})
endforeach()

# Every wing's shared headers, for the tests and benchmarks that measure a wing from inside.
add_library(rtpro_render_internals INTERFACE)
foreach(wing IN LISTS render_wings)
  target_link_libraries(rtpro_render_internals INTERFACE rtpro_render_${wing})
endforeach()
