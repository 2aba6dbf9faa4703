#pragma once
// Whether anything lights a scene under the integrator it is rendered with, so that a scene that
// will render black (a light-less scene file, a Whitted render of a scene lit by emission) is said
// before the render rather than found after it.
#include "rtpro/scene/render_scene.h"

#include <optional>
#include <string>

namespace rtpro {

// One line saying why nothing lights `scene` and how to light it; none when something does: a
// light, or under `path` an environment, a background (a uniform environment) or an emissive
// material.
std::optional<std::string> unlit_scene_warning(const RenderScene& scene);

}  // namespace rtpro
