#include "rtpro/scene/quad_light.h"

#include "traceable_range_check.h"
#include "rtpro/scene/scene_summary.h"

namespace rtpro {

QuadLight light_from(const QuadLightDesc& d) {
  const Vec3 n = cross(d.edge1, d.edge2);
  return QuadLight{d.position - d.edge1 * 0.5f - d.edge2 * 0.5f,
                   d.edge1,
                   d.edge2,
                   normalize(n),
                   length(n),
                   d.color * d.intensity,
                   d.samples};
}

double reach_from_origin(const QuadLightDesc& d) {
  return largest_magnitude(d.position) + double(length(d.edge1) + length(d.edge2));
}

void count_light(const QuadLight&, SceneSummary& summary) { ++summary.area_lights; }

}  // namespace rtpro
