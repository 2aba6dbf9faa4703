// Fuzz target: a scene file with command-line overrides, through parsing and render-scene
// building (instancing, mesh references, glTF files placed by the scene, image texture paths,
// the memory estimate) — everything `rtpro info` does.
//
// Input: optional leading lines "#--set KEY=VALUE" (YAML comments, so the file stays a valid
// scene for the real binary: pass each as --set), then the scene text. The scene sits in the
// fuzz workspace beside tiny.obj, tiny.mtl, tiny.ply, tiny.gltf (one textured triangle, its
// buffer inline) and tiny.png (2x2, the glTF's base colour), so `file: tiny.gltf` places a real
// glTF and `texture: tiny.png` names a real image.
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
    static constexpr char kPng[] =
        "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52\x00\x00\x00\x02\x00\x00\x00\x02\x08"
        "\x02\x00\x00\x00\xfd\xd4\x9a\x73\x00\x00\x00\x10\x49\x44\x41\x54\x78\x9c\x63\xf8\xcf\xc0\x00\x44\x0c"
        "\x10\x0a\x00\x1f\xee\x03\xfd\x8b\x5f\x14\xd4\x00\x00\x00\x00\x49\x45\x4e\x44\xae\x42\x60\x82";
    rtpro::fuzz::write_workspace_file("tiny.png", std::string_view(kPng, sizeof kPng - 1));
    rtpro::fuzz::write_workspace_file(
        "tiny.gltf",
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"indices":2,"material":0}]}],)"
        R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
        R"("textures":[{"source":0}],"images":[{"uri":"tiny.png"}],)"
        R"("buffers":[{"byteLength":68,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/AAABAAIAAAA="}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24},)"
        R"({"buffer":0,"byteOffset":60,"byteLength":6}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
        R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},)"
        R"({"bufferView":2,"componentType":5123,"count":3,"type":"SCALAR"}]})");
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
    overrides.emplace_back(
        text.substr(kOverridePrefix.size(), end == std::string_view::npos ? end : end - kOverridePrefix.size()));
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
