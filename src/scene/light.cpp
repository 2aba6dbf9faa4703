#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/light.h"

namespace rtpro {

namespace {

Light make(const PointLightDesc& d) { return PointLight{d.position, d.color * d.intensity}; }
Light make(const DirectionalLightDesc& d) { return DirectionalLight{-normalize(d.direction), d.color * d.intensity}; }

}  // namespace

Light make_light(const LightDesc& desc) {
  return std::visit([](const auto& d) { return make(d); }, desc);
}

}  // namespace rtpro
