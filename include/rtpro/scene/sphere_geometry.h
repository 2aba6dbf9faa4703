#pragma once
// Spheres, the scene's side of the geometry kind in one place: the entries a scene file writes
// (read in src/scene/yaml/yaml_sphere_entry.cpp), the shapes a render scene stores and what the
// scene needs of them (primitives, bounds, the summary, the cost estimate), defined in
// src/scene/build/sphere_geometry.cpp. Its intersector is geometry/sphere_intersect.h, shared by
// both backends; the kind is registered in scene/render_scene.h (Geometry).
#include "rtpro/core/bbox.h"
#include "rtpro/core/vec3.h"

#include <cstdint>
#include <vector>

namespace rtpro {

struct SphereDesc;  // scene/description.h
struct ShapeTally;  // scene/scene_summary.h
struct SceneSummary;
struct YamlNode;
class ShapeEntryReader;  // src/scene/yaml/yaml_shape_entry.h

struct Sphere {
  Vec3 center;
  float radius;
  std::uint32_t material;
};

struct SphereSet {
  std::vector<Sphere> spheres;
  // Moving spheres (scene/motion.h): sphere i's centre at step j is center_steps[i * step_count
  // + j]; empty when none of the set moves (a set with one moving sphere keys them all).
  std::vector<Vec3> center_steps = {};
  std::uint32_t step_count = 0;

  bool moving() const { return !center_steps.empty(); }
  // Sphere i's centre at ray time `time` in [0, 1] (moving sets only).
  Vec3 center_at(std::uint32_t i, float time) const;
  // Over the whole shutter for a moving set.
  BBox sphere_bounds(std::uint32_t i) const;
  // At one time step (a moving set's), for Embree's per-step bounds.
  BBox sphere_bounds_at_step(std::uint32_t i, std::uint32_t step) const;
};

// `type: sphere` in an object's or the world's list of entries.
inline const char* entry_type_name(const std::vector<SphereDesc>&) { return "sphere"; }
void read_shape_entry(const YamlNode& node, ShapeEntryReader& reader, std::vector<SphereDesc>& spheres);

// One geometry of every sphere an object lists in the scene file, in their order.
SphereSet shapes_from(const std::vector<SphereDesc>& spheres);
std::uint32_t primitive_count_of(const SphereSet& set);
BBox primitive_bounds_of(const SphereSet& set, std::uint32_t prim);  // over the whole shutter
inline std::uint32_t motion_step_count_of(const SphereSet& set) { return set.moving() ? set.step_count : 0; }
inline BBox primitive_bounds_at_step(const SphereSet& set, std::uint32_t prim, std::uint32_t step) {
  return set.sphere_bounds_at_step(prim, step);
}
BBox bounds_of(const SphereSet& set);  // of every sphere
void tally_shapes(const SphereSet& set, ShapeTally& tally, SceneSummary& summary);
// Memory the described shape adds to a render (scene/render_cost.h): a sphere's few dozen bytes
// are left out.
std::uint64_t estimated_bytes(const SphereDesc& sphere);

}  // namespace rtpro
