#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/light.h"

#include <cmath>
#include <numbers>

namespace rtpro {

namespace {

Light make(const PointLightDesc& d) { return PointLight{d.position, d.color * d.intensity}; }
Light make(const SpotLightDesc& d) {
  constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
  // Cosines in double, then rounded: inner <= outer keeps cos_outer <= cos_inner.
  return SpotLight{d.position, normalize(d.direction), d.color * d.intensity,
                   static_cast<float>(std::cos(double(d.inner_angle) * kRadiansPerDegree)),
                   static_cast<float>(std::cos(double(d.outer_angle) * kRadiansPerDegree))};
}
Light make(const DirectionalLightDesc& d) { return DirectionalLight{-normalize(d.direction), d.color * d.intensity}; }
Light make(const SphereLightDesc& d) { return SphereLight{d.center, d.radius, d.color * d.intensity, d.samples}; }
Light make(const QuadLightDesc& d) {
  const Vec3 n = cross(d.edge1, d.edge2);
  return QuadLight{d.position - d.edge1 * 0.5f - d.edge2 * 0.5f, d.edge1, d.edge2, normalize(n), length(n),
                   d.color * d.intensity, d.samples};
}

}  // namespace

Light make_light(const LightDesc& desc) {
  return std::visit([](const auto& d) { return make(d); }, desc);
}

}  // namespace rtpro
