#include "sphere_backend.h"

#include "embree_user_geometry.h"
#include "rtpro/core/avx2_clones.h"

#include <cmath>
#include <string>

namespace rtpro {

std::optional<std::string> embree_refusal(const SphereSet& set) {
  for (std::uint32_t i = 0; i < set.spheres.size(); ++i) {
    const Sphere& s = set.spheres[i];
    // Embree's commit silently drops primitives beyond about 1.8e18 (or NaN/inf): refused here, with
    // the margin is_traceable() keeps for rays.
    const BBox bounds = set.sphere_bounds(i);
    const bool in_range =
        bounds.empty() || (within_traceable_range(bounds.lower) && within_traceable_range(bounds.upper));
    if (!(std::isfinite(s.radius) && s.radius >= 0.0f) || !in_range)
      return "has sphere " + std::to_string(i) + " outside Embree's coordinate range";
  }
  return std::nullopt;
}

namespace {

RTPRO_AVX2_CLONES void intersect_spheres(const RTCIntersectFunctionNArguments* args) {
  intersect_user_primitive<SphereSet>(args);
}

RTPRO_AVX2_CLONES void occlude_spheres(const RTCOccludedFunctionNArguments* args) {
  occlude_user_primitive<SphereSet>(args);
}

}  // namespace

EmbreeGeometry new_embree_geometry(RTCDevice device, const SphereSet& set, RTCBuildQuality quality) {
  return new_embree_user_geometry(device, set, quality, &intersect_spheres, &occlude_spheres);
}

}  // namespace rtpro
