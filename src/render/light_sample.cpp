#include "rtpro/render/light_sample.h"

#include <variant>

namespace rtpro {

namespace {

LightSample sample(const PointLightDesc& light, const Vec3& point) {
  const Vec3 to_light = light.position - point;
  const float distance = length(to_light);
  return {to_light / distance, distance, light.color * light.intensity};
}

LightSample sample(const DirectionalLightDesc& light, const Vec3&) {
  return {-normalize(light.direction), std::numeric_limits<float>::infinity(), light.color * light.intensity};
}

}  // namespace

LightSample sample_light(const LightDesc& light, const Vec3& point) {
  return std::visit([&](const auto& l) { return sample(l, point); }, light);
}

}  // namespace rtpro
