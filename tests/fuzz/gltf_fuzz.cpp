// Fuzz target: a glTF 2.0 file read as a whole scene, as `rtpro render model.glb` reads it —
// tinygltf's parse, rtpro's validation of accessors, buffers and the node tree, the cost check of
// `--max-memory 256`, then the render scene (instances, range checks).
//
// Input: a .glb file when it starts with the GLB magic "glTF", otherwise the JSON of a .gltf file,
// optionally followed by a line "#---bin---" and the bytes of model.bin (which the JSON reaches
// with "uri": "model.bin"). Without the marker there is no model.bin.
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/scene_parser.h"

#include <cstdint>
#include <string_view>

namespace {
constexpr std::string_view kBinMarker = "\n#---bin---\n";
constexpr std::string_view kGlbMagic = "glTF";
constexpr std::uint64_t kBudget = std::uint64_t{256} << 20;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::filesystem::path file;
  if (input.substr(0, kGlbMagic.size()) == kGlbMagic) {
    rtpro::fuzz::remove_workspace_file("model.bin");
    file = rtpro::fuzz::write_workspace_file("model.glb", input);
  } else {
    const std::size_t marker = input.find(kBinMarker);
    if (marker == std::string_view::npos) {
      rtpro::fuzz::remove_workspace_file("model.bin");
    } else {
      rtpro::fuzz::write_workspace_file("model.bin", input.substr(marker + kBinMarker.size()));
    }
    file = rtpro::fuzz::write_workspace_file("model.gltf", input.substr(0, marker));
  }
  try {
    const rtpro::SceneDescription description = rtpro::parse_scene_file(file);
    rtpro::check_render_cost(rtpro::estimate_render_cost(description), kBudget, "fuzz", description.file);
    rtpro::build_render_scene(description);
  } catch (const rtpro::InputError&) {
    // The expected answer to a bad file. Anything else escaping is a finding.
  }
  return 0;
}
