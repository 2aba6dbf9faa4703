#include "rtpro/scene/spot_light.h"

#include "traceable_range_check.h"
#include "rtpro/scene/scene_summary.h"

#include <cmath>
#include <numbers>

namespace rtpro {

SpotLight light_from(const SpotLightDesc& d) {
  constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
  // Cosines in double, then rounded: inner <= outer keeps cos_outer <= cos_inner.
  return SpotLight{d.position, normalize(d.direction), d.color * d.intensity,
                   static_cast<float>(std::cos(double(d.inner_angle) * kRadiansPerDegree)),
                   static_cast<float>(std::cos(double(d.outer_angle) * kRadiansPerDegree))};
}

double reach_from_origin(const SpotLightDesc& d) { return largest_magnitude(d.position); }

void count_light(const SpotLight&, SceneSummary& summary) { ++summary.spot_lights; }

}  // namespace rtpro
