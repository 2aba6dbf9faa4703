#include "rtpro/scene/sphere_light.h"

#include "traceable_range_check.h"
#include "rtpro/scene/scene_summary.h"

namespace rtpro {

SphereLight light_from(const SphereLightDesc& d) {
  return SphereLight{d.center, d.radius, d.color * d.intensity, d.samples};
}

double reach_from_origin(const SphereLightDesc& d) { return largest_magnitude(d.center) + double(d.radius); }

void count_light(const SphereLight&, SceneSummary& summary) { ++summary.area_lights; }

}  // namespace rtpro
