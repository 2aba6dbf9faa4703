#include "hit_prefetch.h"

#include "rtpro/core/overloaded.h"

namespace rtpro {

bool hit_prefetch_pays(const RenderScene& scene) {
  std::size_t bytes = 0;
  const auto add_group = [&](const Group& group) {
    for (const Geometry& geometry : group.geometries)
      std::visit(Overloaded{[&](const SphereSet& set) {
                              bytes += set.spheres.size() * sizeof(Sphere) + set.center_steps.size() * sizeof(Vec3);
                            },
                            [&](const TriangleMesh& mesh) { bytes += mesh.memory_bytes(); },
                            [&](const CurveSet& curves) { bytes += curves.memory_bytes(); },
                            [](const Instance&) {}},  // its prototype's group is counted once
                 geometry);
  };
  add_group(scene.top);
  for (const Group& prototype : scene.prototypes) add_group(prototype);
  return bytes > kHitPrefetchFromBytes;
}

}  // namespace rtpro
