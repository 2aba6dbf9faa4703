#include "rtpro/scene/directional_light.h"

#include "rtpro/scene/scene_summary.h"

namespace rtpro {

DirectionalLight light_from(const DirectionalLightDesc& d) {
  return DirectionalLight{-normalize(d.direction), d.color * d.intensity};
}

double reach_from_origin(const DirectionalLightDesc&) { return 0.0; }

void count_light(const DirectionalLight&, SceneSummary& summary) { ++summary.directional_lights; }

}  // namespace rtpro
