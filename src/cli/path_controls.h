#pragma once
// The path integrator's Light Paths controls (scene/render_settings.h, PathControls) as named
// values, in one order for every place that shows them: `rtpro info`, the EXR metadata and the
// render journal's identity.
#include "rtpro/scene/render_settings.h"

#include <string>
#include <vector>

namespace rtpro::cli {

struct PathControlValue {
  std::string key;  // the scene file's key under render:, e.g. "clamp_indirect"
  double value;     // the value in effect: unset depth limits are max_depth
  std::string text() const;
};

std::vector<PathControlValue> path_control_values(const RenderSettings& settings);

// Whether any control differs from its default (a depth limit set below max_depth, a clamp, a
// filter): only then do they change an image.
bool path_controls_in_effect(const RenderSettings& settings);

// "diffuse/glossy/transmission depth 5/5/5, clamp direct off, clamp indirect 10, filter glossy off".
std::string path_controls_summary(const RenderSettings& settings);

}  // namespace rtpro::cli
