#pragma once
// What a render scene holds, counted without rendering: for `rtpro info` and statistics.
#include "rtpro/core/bbox.h"
#include "rtpro/scene/render_scene.h"

#include <cstddef>
#include <cstdint>

namespace rtpro {

struct SceneSummary {
  std::size_t materials = 0;
  std::size_t point_lights = 0;
  std::size_t spot_lights = 0;
  std::size_t directional_lights = 0;
  std::size_t area_lights = 0;  // sphere and quad lights
  std::size_t prototypes = 0;
  std::size_t instances = 0;
  std::size_t meshes = 0;            // stored meshes (top level and in prototypes)
  std::uint64_t spheres_stored = 0;  // each stored once
  std::uint64_t triangles_stored = 0;
  std::uint64_t vertices_stored = 0;
  std::uint64_t spheres_rendered = 0;  // after instancing: what the camera can see
  std::uint64_t triangles_rendered = 0;
  std::uint64_t curve_segments_stored = 0;
  std::uint64_t curve_segments_rendered = 0;
  BBox bounds;
  std::size_t geometry_bytes = 0;       // spheres, vertices, indices, normals, materials
  std::size_t estimated_bvh_bytes = 0;  // native BVH, from primitive counts
  // What moves during the shutter (scene/motion.h), and the most time steps any of it takes.
  struct Motion {
    std::size_t moving_instances = 0, transform_steps = 0;
    std::size_t deforming_meshes = 0, vertex_steps = 0;
    std::uint64_t moving_spheres = 0;
    std::size_t center_steps = 0;
    bool camera_moves = false;
    bool any() const { return moving_instances + deforming_meshes + moving_spheres > 0 || camera_moves; }
  } motion;
};

// What one group's shapes add up to, each kind of shape adding its own (tally_shapes, in the
// kind's file): spheres and triangles count again for every instance that places the group.
struct ShapeTally {
  std::uint64_t spheres = 0, triangles = 0, curve_segments = 0;
  std::size_t primitives = 0;  // what the native BVH holds references to
};

SceneSummary summarize(const RenderScene& scene);

}  // namespace rtpro
