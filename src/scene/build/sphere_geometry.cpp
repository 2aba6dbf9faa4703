#include "rtpro/scene/sphere_geometry.h"

#include "rtpro/scene/description.h"
#include "rtpro/scene/motion.h"
#include "rtpro/scene/scene_summary.h"

#include <algorithm>
#include <span>

namespace rtpro {

BBox SphereSet::sphere_bounds(std::uint32_t i) const {
  const Sphere& s = spheres[i];
  BBox box{s.center - Vec3(s.radius), s.center + Vec3(s.radius)};
  for (std::uint32_t step = 0; step < step_count; ++step) box.extend(sphere_bounds_at_step(i, step));
  return box;
}

BBox SphereSet::sphere_bounds_at_step(std::uint32_t i, std::uint32_t step) const {
  const Vec3 center = center_steps[std::size_t{i} * step_count + step];
  return {center - Vec3(spheres[i].radius), center + Vec3(spheres[i].radius)};
}

Vec3 SphereSet::center_at(std::uint32_t i, float time) const {
  return value_at_time(std::span<const Vec3>(center_steps.data() + std::size_t{i} * step_count, step_count), time);
}

SphereSet shapes_from(const std::vector<SphereDesc>& spheres) {
  SphereSet set;
  set.spheres.reserve(spheres.size());
  std::size_t steps = 0;
  for (const SphereDesc& s : spheres) {
    set.spheres.push_back({s.center, s.radius, s.material});
    steps = std::max(steps, s.center_steps.size());
  }
  if (steps == 0) return set;
  // One step count for the set: the others' steps resampled, the static spheres' repeated.
  set.step_count = static_cast<std::uint32_t>(steps);
  for (const SphereDesc& s : spheres) {
    const std::vector<Vec3> own = s.center_steps.empty()
                                      ? std::vector<Vec3>(steps, s.center)
                                      : resample_steps<Vec3>(s.center_steps, static_cast<int>(steps));
    set.center_steps.insert(set.center_steps.end(), own.begin(), own.end());
  }
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
  summary.geometry_bytes += set.spheres.capacity() * sizeof(Sphere) + set.center_steps.capacity() * sizeof(Vec3);
  tally.primitives += set.spheres.size();
  if (set.moving()) {
    summary.motion.moving_spheres += set.spheres.size();
    summary.motion.center_steps = std::max<std::size_t>(summary.motion.center_steps, set.step_count);
  }
}

std::uint64_t estimated_bytes(const SphereDesc&) { return 0; }

}  // namespace rtpro
