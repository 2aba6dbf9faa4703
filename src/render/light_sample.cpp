#include "rtpro/render/light_sample.h"

#include <limits>
#include <variant>

namespace rtpro {

namespace {

LightSample sample(const PointLight& light, const Vec3& point) {
  const Vec3 to_light = light.position - point;
  const float distance = length(to_light);
  return {to_light / distance, distance, light.radiance};
}

LightSample sample(const DirectionalLight& light, const Vec3&) {
  return {light.to_light, std::numeric_limits<float>::infinity(), light.radiance};
}

}  // namespace

LightSample sample_light(const Light& light, const Vec3& point) {
  return std::visit([&](const auto& l) { return sample(l, point); }, light);
}

}  // namespace rtpro
