#include "rtpro/scene/sphere_geometry.h"

#include "rtpro/scene/description.h"
#include "rtpro/scene/scene_summary.h"

namespace rtpro {

BBox SphereSet::sphere_bounds(std::uint32_t i) const {
  const Sphere& s = spheres[i];
  return {s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
}

SphereSet shapes_from(const std::vector<SphereDesc>& spheres) {
  SphereSet set;
  set.spheres.reserve(spheres.size());
  for (const SphereDesc& s : spheres) set.spheres.push_back({s.center, s.radius, s.material});
  return set;
}

std::uint32_t primitive_count_of(const SphereSet& set) { return static_cast<std::uint32_t>(set.spheres.size()); }

BBox primitive_bounds_of(const SphereSet& set, std::uint32_t prim) { return set.sphere_bounds(prim); }

BBox bounds_of(const SphereSet& set) {
  BBox b;
  for (std::uint32_t i = 0; i < primitive_count_of(set); ++i) b.extend(set.sphere_bounds(i));
  return b;
}

void tally_shapes(const SphereSet& set, ShapeTally& tally, SceneSummary& summary) {
  tally.spheres += set.spheres.size();
  summary.geometry_bytes += set.spheres.capacity() * sizeof(Sphere);
  tally.primitives += set.spheres.size();
}

std::uint64_t estimated_bytes(const SphereDesc&) { return 0; }

}  // namespace rtpro
