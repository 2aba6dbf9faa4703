#pragma once
// Settings a render will not read, said before it rather than left for the user to find in the
// image: the path integrator's controls (Cycles' Light Paths: per-lobe depths, clamps, Filter
// Glossy) given to a render of the whitted integrator, which has none of them.
#include "rtpro/scene/render_settings.h"

#include <optional>
#include <string>

namespace rtpro {

// One line naming the path-only controls `render` sets that its integrator ignores; none when it
// sets none, or renders with the path integrator.
std::optional<std::string> ignored_path_controls_warning(const RenderSettings& render);

}  // namespace rtpro
