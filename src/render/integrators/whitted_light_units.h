#pragma once
// The Whitted integrator's light units (scene/render_settings.h): a scene in `whitted` units (the
// default under this integrator) lights with its values as they are; a `radiometric` scene's lights
// are converted, so one scene renders alike under both integrators.
#include "light_sample.h"
#include "rtpro/scene/render_scene.h"

#include <numbers>
#include <variant>

namespace rtpro {

// Whether the scene's lights are in radiometric units (unset: this integrator's own, whitted's).
inline bool is_radiometric(const RenderScene& scene) {
  return scene.render.light_units.value_or(LightUnits::kWhitted) == LightUnits::kRadiometric;
}

// Whether a colour is zero in every channel (a light that sends nothing, a spot light's sample
// outside its cone).
inline bool is_black(const Color& c) { return c.x == 0.0f && c.y == 0.0f && c.z == 0.0f; }

// Light sample `ls` of `light` in whitted light units: from a radiometric scene's light divided by
// π, and by d² for point and spot lights.
inline LightSample in_whitted_units(const Light& light, LightSample ls, bool radiometric) {
  if (!radiometric) return ls;
  const bool falls_off = std::holds_alternative<PointLight>(light) || std::holds_alternative<SpotLight>(light);
  ls.radiance = ls.radiance * (falls_off ? std::numbers::inv_pi_v<float> / (ls.distance * ls.distance)
                                         : std::numbers::inv_pi_v<float>);
  return ls;
}

}  // namespace rtpro
