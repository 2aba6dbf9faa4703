// glTF base colour textures through the real binary, on the Khronos BoxTextured sample of Debian's
// assimp-testmodels: the texture as a file beside the .gltf, inside the .glb (a buffer view) and
// as a data: URI give the same picture (with the same sampler), and it is the textured one. Hand-made quads are in
// gltf_texture_slots_test.cpp.
#include "rtpro/image/image_io.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace rtpro {
namespace gltf_texture_test {

const std::filesystem::path kSamples = "/usr/share/assimp/models/glTF2";

TEST(GltfTexture, FileBufferViewAndDataUriGiveTheSameTexturedBox) {
  if (!std::filesystem::exists(kSamples / "BoxTextured-glTF-Binary/BoxTextured.glb"))
    GTEST_SKIP() << "assimp-testmodels is not installed";
  const auto dir = test::scratch_dir();
  const std::vector<std::filesystem::path> variants{kSamples / "BoxTextured-glTF/BoxTextured.gltf",
                                                    kSamples / "BoxTextured-glTF-Binary/BoxTextured.glb",
                                                    kSamples / "BoxTextured-glTF-Embedded/BoxTextured.gltf"};
  std::vector<Image> images;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const auto out = dir / ("box" + std::to_string(i) + ".exr");
    std::string output;
    ASSERT_EQ(test::run_command(test::rtpro_executable().string() + " render " + variants[i].string() + " -o " +
                                    out.string() + " --size 96x72 --spp 4 -q",
                                &output),
              0)
        << output;
    images.push_back(read_image(out));
  }
  // The .glb and the data: URI variants share their sampler (REPEAT); the plain .gltf's is
  // MIRRORED_REPEAT across and CLAMP_TO_EDGE down, which shows where coordinates touch the edges.
  EXPECT_EQ(std::memcmp(images[1].data.data(), images[2].data.data(), images[1].data.size() * sizeof(float)), 0)
      << variants[2] << " differs from " << variants[1];
  // The texture (a green and blue logo on white) shows: the box's pixels are not all grey.
  float most_saturated = 0.0f;
  for (std::size_t p = 0; p < images[0].data.size(); p += 3) {
    const float r = images[0].data[p], g = images[0].data[p + 1], b = images[0].data[p + 2];
    most_saturated = std::max(most_saturated, std::max({r, g, b}) - std::min({r, g, b}));
  }
  EXPECT_GT(most_saturated, 0.1f);
}

}  // namespace gltf_texture_test
}  // namespace rtpro
