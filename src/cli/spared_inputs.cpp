#include "spared_inputs.h"

#include "output_target.h"
#include "render_output.h"
#include "rtpro/job/journal_owner.h"

namespace rtpro::cli {

namespace {

// How a message names an input: "the scene file", "the scene's texture".
std::string input_role(const std::string& kind) {
  if (kind == "scene") return "the scene file";
  if (kind == "mesh data") return "a file the scene's meshes read";
  if (kind == "environment") return "the scene's environment map";
  return "the scene's " + kind;
}

std::vector<NamedPath> request_outputs(const RenderRequest& request) {
  std::vector<NamedPath> outputs;
  if (!request.output.to_stdout()) {
    outputs.push_back({"-o", request.output.file().string()});
    outputs.push_back({"the partial image of -o", partial_path(request.output.file()).string()});
  }
  outputs.push_back({"--stats-json", request.stats_json});
  if (!request.journal.empty()) {
    outputs.push_back({"the resume journal", request.journal.string()});
    outputs.push_back({"the resume journal's lock", journal_lock_path(request.journal).string()});
  }
  return outputs;
}

}  // namespace

void check_outputs_spare_inputs(const RenderRequest& request, const std::vector<SceneInput>& inputs) {
  std::vector<NamedPath> read;
  read.reserve(inputs.size());
  for (const SceneInput& input : inputs) read.push_back({input_role(input.kind), input.file.string()});
  for (const NamedPath& output : request_outputs(request)) check_output_is_distinct(output, read);
}

}  // namespace rtpro::cli
