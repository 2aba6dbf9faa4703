// No output replaces a file the scene reads (issue 43): -o, --stats-json (and the journal beside
// -o) pointed at an include, a mesh, an MTL library, a glTF file or its buffer, a texture or the
// environment map are refused with exit 2 naming both, however the path is spelled; the input
// keeps its bytes. Likewise `rtpro denoise X -o X`.
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace rtpro::test {
namespace outputs_spare_inputs_test {

// A glTF triangle whose positions are in tri.bin beside it.
constexpr const char* kGltf = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                 "min": [0, 0, 0], "max": [1, 1, 0]}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}], "buffers": [{"uri": "tri.bin", "byteLength": 36}]})";

// The scene and every kind of file it reads, in one scratch folder; returns the scene.
std::filesystem::path write_scene_with_inputs() {
  scratch_dir();
  const auto scene = write_file("scene.yaml", R"(rtpro: 1
include: inc.yaml
camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, resolution: [8, 8]}
render: {spp: 1}
materials:
  globe: {color: {texture: tex.png}}
environment: {file: env.exr}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: globe}
  - {type: mesh, file: tri.obj}
  - {type: mesh, file: tri.gltf}
)");
  write_file("inc.yaml", "lights: [{type: point, position: [0, 5, 5], intensity: 1}]\n");
  write_file("tri.obj", "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
  write_file("tri.mtl", "newmtl red\nKd 1 0 0\n");
  write_file("tri.gltf", kGltf);
  const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  write_file("tri.bin", std::string(reinterpret_cast<const char*>(positions), sizeof positions));
  const auto dir = scene.parent_path();
  std::filesystem::copy_file(scenes_dir() / "textures" / "uv_grid.png", dir / "tex.png");
  std::filesystem::copy_file(scenes_dir() / "environments" / "sunset.exr", dir / "env.exr");
  std::filesystem::create_directory(dir / "sub");
  return scene;
}

struct Clash {
  std::string option;  // "-o" or "--stats-json"
  std::string target;  // relative to the scene's folder
  std::string input;   // the file it names, as the scene names it
};

TEST(OutputsSpareInputs, AnOutputNamingAnyFileTheSceneReadsIsRefusedAndTheInputKept) {
  const auto scene = write_scene_with_inputs();
  const auto dir = scene.parent_path();
  std::filesystem::create_directory_symlink(dir, dir / "here");
  std::filesystem::create_hard_link(dir / "tri.mtl", dir / "hard.json");
  const std::vector<Clash> clashes = {
      {"--stats-json", "inc.yaml", "inc.yaml"},
      {"--stats-json", "tri.obj", "tri.obj"},
      {"--stats-json", "tri.mtl", "tri.mtl"},
      {"--stats-json", "tri.gltf", "tri.gltf"},
      {"--stats-json", "tri.bin", "tri.bin"},
      {"--stats-json", "tex.png", "tex.png"},
      {"--stats-json", "env.exr", "env.exr"},
      {"-o", "tex.png", "tex.png"},
      {"-o", "env.exr", "env.exr"},
      {"-o", "sub/../tex.png", "tex.png"},
      {"-o", "here/tex.png", "tex.png"},
      {"--stats-json", "hard.json", "tri.mtl"},
  };
  for (const Clash& clash : clashes) {
    SCOPED_TRACE(clash.option + " " + clash.target);
    const std::string before = read_file(dir / clash.input);
    const std::string output = clash.option == "-o" ? clash.target : "out.exr";
    std::string args = "render scene.yaml -o " + output + " -q";
    if (clash.option != "-o") args += " " + clash.option + " " + clash.target;
    std::string out;
    EXPECT_EQ(run_command("cd " + dir.string() + " && " + rtpro_command(args), &out), 2) << out;
    EXPECT_NE(out.find(clash.option + " " + clash.target + " is the same file as"), std::string::npos) << out;
    EXPECT_NE(out.find(clash.input + ": writing it would replace that"), std::string::npos) << out;
    EXPECT_EQ(read_file(dir / clash.input), before);
    EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
  }
  // The same scene with outputs of their own renders.
  std::string out;
  EXPECT_EQ(run_command("cd " + dir.string() + " && " +
                            rtpro_command("render scene.yaml -o out.exr -q --stats-json stats.json"),
                        &out),
            0)
      << out;
}

// A file the scene names is spared before anything is loaded: the refusal of an output naming
// the texture comes before the broken mesh beside it is read (a large scene is not loaded only to
// be refused).
TEST(OutputsSpareInputs, AnOutputNamingAFileTheSceneNamesIsRefusedBeforeLoading) {
  const auto scene = write_scene_with_inputs();
  const auto dir = scene.parent_path();
  write_file("tri.obj", "v 0 0 0\nf 1 2 7\n");
  std::string out;
  EXPECT_EQ(run_command("cd " + dir.string() + " && " + rtpro_command("render scene.yaml -o tex.png -q"), &out), 2)
      << out;
  EXPECT_NE(out.find("-o tex.png is the same file as the scene's texture tex.png"), std::string::npos) << out;
  EXPECT_EQ(out.find("tri.obj"), std::string::npos) << out;
  // Without the clash, the broken mesh is what is refused.
  EXPECT_EQ(run_command("cd " + dir.string() + " && " + rtpro_command("render scene.yaml -o out.exr -q"), &out), 2)
      << out;
  EXPECT_NE(out.find("tri.obj"), std::string::npos) << out;
}

TEST(OutputsSpareInputs, DenoisingAnImageOntoItselfIsRefused) {
  const auto scene = write_scene_with_inputs();
  const auto dir = scene.parent_path();
  run_rtpro(render_args(scene, dir / "noisy.exr", "-q --aov albedo,normal,depth"), 0);
  const std::string before = read_file(dir / "noisy.exr");
  std::string out;
  EXPECT_EQ(run_command("cd " + dir.string() + " && " + rtpro_command("denoise noisy.exr -o ./sub/../noisy.exr"), &out),
            2)
      << out;
  EXPECT_NE(out.find("-o ./sub/../noisy.exr is the same file as the input noisy.exr"), std::string::npos) << out;
  EXPECT_EQ(read_file(dir / "noisy.exr"), before);
}

}  // namespace outputs_spare_inputs_test
}  // namespace rtpro::test
