#include "rtpro/scene/point_light.h"

#include "traceable_range_check.h"
#include "rtpro/scene/scene_summary.h"

namespace rtpro {

PointLight light_from(const PointLightDesc& d) { return PointLight{d.position, d.color * d.intensity}; }

double reach_from_origin(const PointLightDesc& d) { return largest_magnitude(d.position); }

void count_light(const PointLight&, SceneSummary& summary) { ++summary.point_lights; }

}  // namespace rtpro
