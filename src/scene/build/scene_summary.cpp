#include "rtpro/scene/scene_summary.h"

#include "rtpro/core/overloaded.h"

#include <variant>

namespace rtpro {

namespace {

struct GroupCounts {
  std::uint64_t spheres = 0, triangles = 0;
};

GroupCounts count_shapes(const Group& group, SceneSummary& summary, std::size_t& primitives) {
  GroupCounts counts;
  for (const Geometry& g : group.geometries) {
    std::visit(Overloaded{[&](const SphereSet& set) {
                            counts.spheres += set.spheres.size();
                            summary.geometry_bytes += set.spheres.capacity() * sizeof(Sphere);
                            primitives += set.spheres.size();
                          },
                          [&](const TriangleMesh& mesh) {
                            ++summary.meshes;
                            counts.triangles += mesh.triangles.size();
                            summary.vertices_stored += mesh.vertices.size();
                            summary.geometry_bytes += mesh.memory_bytes();
                            primitives += mesh.triangles.size();
                          },
                          [&](const Instance&) { ++primitives; }},
               g);
  }
  return counts;
}

}  // namespace

SceneSummary summarize(const RenderScene& scene) {
  SceneSummary s;
  s.materials = scene.materials.size();
  for (const Light& light : scene.lights) {
    std::visit(Overloaded{[&](const PointLight&) { ++s.point_lights; },
                          [&](const SpotLight&) { ++s.spot_lights; },
                          [&](const DirectionalLight&) { ++s.directional_lights; },
                          [&](const SphereLight&) { ++s.area_lights; },
                          [&](const QuadLight&) { ++s.area_lights; }},
               light);
  }
  s.prototypes = scene.prototypes.size();

  std::size_t primitives = 0;
  const GroupCounts top = count_shapes(scene.top, s, primitives);
  std::vector<GroupCounts> per_prototype;
  for (const Group& prototype : scene.prototypes) per_prototype.push_back(count_shapes(prototype, s, primitives));

  s.spheres_stored = s.spheres_rendered = top.spheres;
  s.triangles_stored = s.triangles_rendered = top.triangles;
  for (const GroupCounts& c : per_prototype) {
    s.spheres_stored += c.spheres;
    s.triangles_stored += c.triangles;
  }
  for (const Geometry& g : scene.top.geometries) {
    if (const auto* instance = std::get_if<Instance>(&g)) {
      ++s.instances;
      s.spheres_rendered += per_prototype[instance->prototype].spheres;
      s.triangles_rendered += per_prototype[instance->prototype].triangles;
    }
  }
  s.bounds = scene.bounds();
  // The native BVH: one 8-byte reference per primitive and about one 32-byte node per two.
  s.estimated_bvh_bytes = primitives * (8 + 16);
  return s;
}

}  // namespace rtpro
