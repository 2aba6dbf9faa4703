#include "rtpro/scene/unused_settings.h"

#include <vector>

namespace rtpro {

std::optional<std::string> ignored_path_controls_warning(const RenderSettings& render) {
  switch (render.integrator) {
    case Integrator::kPath: return std::nullopt;
    case Integrator::kWhitted: break;
  }
  const PathControls& path = render.path;
  std::vector<const char*> set;
  if (path.max_diffuse_depth) set.push_back("max_diffuse_depth");
  if (path.max_glossy_depth) set.push_back("max_glossy_depth");
  if (path.max_transmission_depth) set.push_back("max_transmission_depth");
  if (path.max_volume_depth) set.push_back("max_volume_depth");
  if (path.clamp_direct > 0.0f) set.push_back("clamp_direct");
  if (path.clamp_indirect > 0.0f) set.push_back("clamp_indirect");
  if (path.filter_glossy > 0.0f) set.push_back("filter_glossy");
  if (set.empty()) return std::nullopt;
  std::string names;
  for (const char* name : set) names += std::string(names.empty() ? "" : ", ") + "render." + name;
  return names + (set.size() == 1 ? " is" : " are") +
         " read by the path integrator only; the whitted integrator renders without " +
         (set.size() == 1 ? "it" : "them") + " (--integrator path to use " + (set.size() == 1 ? "it)" : "them)");
}

}  // namespace rtpro
