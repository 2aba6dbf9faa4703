#include "backend_options.h"

#include "choice_option.h"

#include <map>
#include <string>

namespace rtpro::cli {

void add_embree_options(CLI::App& command, BackendOptions& options) {
  static const std::map<std::string, EmbreeBuildQuality> kQualities = {
      {"low", EmbreeBuildQuality::kLow}, {"medium", EmbreeBuildQuality::kMedium}, {"high", EmbreeBuildQuality::kHigh}};
  one_of(command.add_option_function<std::string>(
             "--embree-quality", [&options](const std::string& name) { options.embree_quality = kQualities.at(name); },
             "Embree BVH build quality: low (fastest build), medium or high (fastest traversal)"),
         {"low", "medium", "high"})
      ->option_text("low|medium|high (default: medium)");
  command.add_flag(
      "--embree-robust,!--no-embree-robust", options.embree_robust,
      "Embree robust traversal (default on; groups of curves alone go without): rays that graze edges never slip "
      "between triangles");
}

}  // namespace rtpro::cli
