// Image textures against the render's memory budget (issue 28): a texture's decoded floats and
// the copies preparing it makes count against --max-memory, from its header, before decoding;
// the refusal names the image and where the scene named it.
#include "rtpro/image/image_io.h"
#include "test_fixtures.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace texture_memory_test {

using test::expect_rtpro_answer;
using test::render_args;
using test::run_rtpro;

TEST(TextureMemory, ATextureOverMaxMemoryIsRefusedBeforeItIsDecoded) {
  const auto dir = test::scratch_dir();
  // 2048 x 2048 x (4 x 3 + 40) bytes: 208 MiB to prepare, within the default budget, over 128 MiB.
  write_image(dir / "big.png", test::gradient_image(2048, 2048), {});
  const auto scene = test::write_file("scene.yaml", R"(rtpro: 1
camera: {position: [0, 0, 4], look_at: [0, 0, 0], resolution: [16, 16]}
materials:
  textured: {color: {texture: big.png}}
lights: [{type: point, position: [2, 2, 4], intensity: 1}]
world: [{type: sphere, material: textured}]
)");
  std::string out =
      expect_rtpro_answer(render_args(scene, dir / "a.png") + " --progress never --max-memory 128", 2, "big.png");
  EXPECT_NE(out.find("with its linear and mip-mapped texture copies"), std::string::npos) << out;
  // And where the scene named it: line 4, the material's texture key.
  EXPECT_NE(out.find("(the texture named at " + scene.string() + ":4:"), std::string::npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.png"));
  out = run_rtpro(render_args(scene, dir / "b.png") + " --progress never --max-memory 512", 0);
}

}  // namespace texture_memory_test
}  // namespace rtpro
