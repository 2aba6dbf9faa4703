// Text from the scene or the command line echoed in a message never reaches the terminal raw
// (issue 43): an escape sequence could recolour or rewrite what rtpro printed, a newline forge a
// line of its own. Each case is one command with ESC and a newline in one piece of input; every
// line rtpro prints must start with "rtpro" and no ESC byte may appear.
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <string>
#include <vector>

namespace rtpro::test {
namespace escaped_messages_test {

// ESC [31m (red) and a newline starting a forged message: as a YAML double-quoted scalar, and raw.
constexpr const char* kYamlHostile = R"("x\e[31m\nforged")";
const std::string kHostile = "x\x1b[31m\nforged";

// `arg` as one word for sh: single quotes keep ESC and newlines as they are.
std::string quoted(const std::string& arg) {
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

constexpr const char* kCamera = "camera: {position: [0, 0, 5], look_at: [0, 0, 0], fov: 40, resolution: [4, 4]}\n";

std::string scene_with(const std::string& lines) { return std::string("rtpro: 1\n") + kCamera + lines; }

struct Case {
  const char* kind;
  std::string scene;              // the scene file's text ("" for scene.yaml unused)
  std::vector<std::string> args;  // after `rtpro`; "SCENE" stands for the scene file
};

std::vector<Case> cases() {
  const std::string h = kYamlHostile;
  return {
      {"unknown top-level key", scene_with(h + ": 1\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"unknown material name",
       scene_with("world: [{type: sphere, radius: 1, material: " + h + "}]\n"),
       {"render", "SCENE", "-o", "o.exr"}},
      {"bad enum value", scene_with("render: {integrator: " + h + "}\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"bad number", scene_with("render: {spp: " + h + "}\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"unknown shape type", scene_with("world: [{type: " + h + "}]\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"unknown object",
       scene_with("world: [{type: instance, object: " + h + "}]\n"),
       {"render", "SCENE", "-o", "o.exr"}},
      {"missing mesh file", scene_with("world: [{type: mesh, file: " + h + "}]\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"missing include", scene_with("include: " + h + "\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"missing texture",
       scene_with("materials: {m: {color: {texture: " + h + "}}}\n"),
       {"render", "SCENE", "-o", "o.exr"}},
      {"missing environment", scene_with("environment: {file: " + h + "}\n"), {"render", "SCENE", "-o", "o.exr"}},
      {"unknown light in a link",
       scene_with("world: [{type: sphere, radius: 1, light_linking: {lights: [" + h + "]}}]\n"),
       {"render", "SCENE", "-o", "o.exr"}},
      {"--set key", scene_with(""), {"render", "SCENE", "-o", "o.exr", "--set", "render." + kHostile + "=1"}},
      {"--set value", scene_with(""), {"render", "SCENE", "-o", "o.exr", "--set", "render.spp=" + kHostile}},
      {"--backend", scene_with(""), {"render", "SCENE", "-o", "o.exr", "--backend", kHostile}},
      {"--aov", scene_with(""), {"render", "SCENE", "-o", "o.exr", "--aov", kHostile}},
      {"--region", scene_with(""), {"render", "SCENE", "-o", "o.exr", "--region", kHostile}},
      {"-o folder", scene_with(""), {"render", "SCENE", "-o", "no" + kHostile + "/o.exr"}},
      {"scene path", "", {"render", "no" + kHostile + ".yaml", "-o", "o.exr"}},
      {"unknown option", "", {"render", "--" + kHostile}},
      {"denoise input", "", {"denoise", "no" + kHostile + ".exr", "-o", "o.exr"}},
  };
}

TEST(EscapedMessages, InputTextInEveryKindOfMessageIsEscaped) {
  const auto dir = scratch_dir();
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.kind);
    const auto scene = write_file("scene.yaml", c.scene);
    std::string command = "cd " + dir.string() + " && " + rtpro_executable().string();
    for (const std::string& arg : c.args) command += " " + quoted(arg == "SCENE" ? scene.string() : arg);
    std::string out;
    EXPECT_NE(run_command(command, &out), 0) << out;
    EXPECT_EQ(out.find('\x1b'), std::string::npos) << out;
    for (std::size_t start = 0; start < out.size();) {
      EXPECT_EQ(out.compare(start, 5, "rtpro"), 0) << "a line not rtpro's in:\n" << out;
      const std::size_t end = out.find('\n', start);
      start = end == std::string::npos ? out.size() : end + 1;
    }
  }
}

// An environment map or texture that is a FIFO or a folder is named for what it is, not "not found".
TEST(EscapedMessages, AnImageThatIsAFifoOrAFolderIsNamedForWhatItIs) {
  const auto dir = scratch_dir();
  ASSERT_EQ(::mkfifo((dir / "pipe.exr").c_str(), 0600), 0);
  std::filesystem::create_directory(dir / "folder.exr");
  for (const auto& [name, kind] :
       {std::pair{"pipe.exr", "a FIFO (named pipe)"}, std::pair{"folder.exr", "a directory"}})
    for (const std::string& entry : {"environment: {file: " + std::string(name) + "}\n",
                                     "materials: {m: {color: {texture: " + std::string(name) + "}}}\n"}) {
      const auto scene = write_file("scene.yaml", scene_with(entry));
      expect_rtpro_answer(render_args(scene, dir / "o.exr"), 2, std::string(name) + "' is " + kind + ", not a file");
    }
}

// Thresholds too small for float sums (and for 1/threshold to fit a sample count) are refused.
TEST(EscapedMessages, ANoiseThresholdTooSmallToMeasureIsRefused) {
  const auto scene = write_file("scene.yaml", scene_with("render: {spp: 4, sampler: sobol}\n"));
  for (const char* threshold : {"1e-20", "1e-50", "1e-7"})
    expect_rtpro_answer(
        render_args(scene, scene.parent_path() / "o.exr", std::string("--noise-threshold ") + threshold), 2,
        "--noise-threshold must be 0");
  run_rtpro(render_args(scene, scene.parent_path() / "o.exr", "--noise-threshold 1e-6 -q"), 0);
}

}  // namespace escaped_messages_test
}  // namespace rtpro::test
