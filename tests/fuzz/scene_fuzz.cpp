// Fuzz target: a scene file with command-line overrides, through parsing and render-scene
// building (instancing, mesh references, the memory estimate) — everything `rtpro info` does.
//
// Input: optional leading lines "#--set KEY=VALUE" (YAML comments, so the file stays a valid
// scene for the real binary: pass each as --set), then the scene text. The scene sits in the
// fuzz workspace beside tiny.obj, tiny.mtl and tiny.ply, so `file: tiny.obj` loads a real mesh.
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/render_cost.h"
#include "rtpro/scene/scene_parser.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr std::string_view kOverridePrefix = "#--set ";
constexpr std::size_t kMaxOverrides = 8;
constexpr std::uint64_t kBudget = std::uint64_t{256} << 20;

void write_meshes_once() {
  static const bool written = [] {
    rtpro::fuzz::write_workspace_file("tiny.obj", "mtllib tiny.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    rtpro::fuzz::write_workspace_file("tiny.mtl", "newmtl red\nKd 1 0 0\n");
    rtpro::fuzz::write_workspace_file("tiny.ply",
                                      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                      "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    return true;
  }();
  (void)written;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  write_meshes_once();
  std::string_view text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> overrides;
  while (overrides.size() < kMaxOverrides && text.substr(0, kOverridePrefix.size()) == kOverridePrefix) {
    const std::size_t end = text.find('\n');
    overrides.emplace_back(text.substr(kOverridePrefix.size(), end == std::string_view::npos ? end : end - kOverridePrefix.size()));
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
  }
  try {
    const rtpro::SceneDescription description =
        rtpro::parse_scene_text(text, rtpro::fuzz::workspace() / "scene.yaml", overrides);
    // What `rtpro render --max-memory 256` checks before it builds anything.
    rtpro::check_render_cost(rtpro::estimate_render_cost(description), kBudget, "fuzz", description.file);
    rtpro::build_render_scene(description);
  } catch (const rtpro::InputError&) {
    // The expected answer to a bad scene. Anything else escaping is a finding.
  }
  return 0;
}
