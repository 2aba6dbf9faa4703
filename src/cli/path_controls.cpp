#include "path_controls.h"

#include <sstream>

namespace rtpro::cli {

std::string PathControlValue::text() const {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::vector<PathControlValue> path_control_values(const RenderSettings& settings) {
  const LobeDepths depths = lobe_depths(settings);
  const PathControls& p = settings.path;
  return {{"max_diffuse_depth", static_cast<double>(depths.diffuse)},
          {"max_glossy_depth", static_cast<double>(depths.glossy)},
          {"max_transmission_depth", static_cast<double>(depths.transmission)},
          {"clamp_direct", p.clamp_direct},
          {"clamp_indirect", p.clamp_indirect},
          {"filter_glossy", p.filter_glossy}};
}

bool path_controls_in_effect(const RenderSettings& settings) {
  const LobeDepths depths = lobe_depths(settings);
  const int all = settings.max_depth;
  const PathControls& p = settings.path;
  return depths.diffuse < all || depths.glossy < all || depths.transmission < all || p.clamp_direct > 0.0f ||
         p.clamp_indirect > 0.0f || p.filter_glossy > 0.0f;
}

std::string path_controls_summary(const RenderSettings& settings) {
  const LobeDepths depths = lobe_depths(settings);
  const PathControls& p = settings.path;
  const auto number_or_off = [](float value) {
    if (!(value > 0.0f)) return std::string("off");
    std::ostringstream out;
    out << value;
    return out.str();
  };
  return "diffuse/glossy/transmission depth " + std::to_string(depths.diffuse) + "/" + std::to_string(depths.glossy) +
         "/" + std::to_string(depths.transmission) + ", clamp direct " + number_or_off(p.clamp_direct) +
         ", clamp indirect " + number_or_off(p.clamp_indirect) + ", filter glossy " + number_or_off(p.filter_glossy);
}

}  // namespace rtpro::cli
