#include "backend_options.h"

#include <cctype>
#include <map>
#include <string>

namespace rtpro::cli {

void add_embree_options(CLI::App& command, BackendOptions& options) {
  static const std::map<std::string, EmbreeBuildQuality> kQualities = {
      {"low", EmbreeBuildQuality::kLow}, {"medium", EmbreeBuildQuality::kMedium}, {"high", EmbreeBuildQuality::kHigh}};
  // IsMember has accepted the name in any case before the function runs.
  command
      .add_option_function<std::string>(
          "--embree-quality",
          [&options](std::string name) {
            for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            options.embree_quality = kQualities.at(name);
          },
          "Embree BVH build quality: low (fastest build), medium or high (fastest traversal)")
      ->check(CLI::IsMember({"low", "medium", "high"}, CLI::ignore_case))
      ->option_text("low|medium|high (default: medium)");
  command.add_flag("--embree-robust,!--no-embree-robust", options.embree_robust,
                   "Embree robust traversal (default on): rays that graze edges never slip between triangles");
}

}  // namespace rtpro::cli
