// glTF base colour textures through the real binary, on the Khronos BoxTextured sample of Debian's
// assimp-testmodels: the texture as a file beside the .gltf, inside the .glb (a buffer view) and
// as a data: URI give the same picture, and it is the textured one. And on a hand-made quad: the
// image is the right way up.
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
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
  for (std::size_t i = 1; i < images.size(); ++i)
    EXPECT_EQ(std::memcmp(images[0].data.data(), images[i].data.data(), images[0].data.size() * sizeof(float)), 0)
        << variants[i] << " differs from " << variants[0];
  // The texture (a green and blue logo on white) shows: the box's pixels are not all grey.
  float most_saturated = 0.0f;
  for (std::size_t p = 0; p < images[0].data.size(); p += 3) {
    const float r = images[0].data[p], g = images[0].data[p + 1], b = images[0].data[p + 2];
    most_saturated = std::max(most_saturated, std::max({r, g, b}) - std::min({r, g, b}));
  }
  EXPECT_GT(most_saturated, 0.1f);
}

// By the glTF specification texture coordinate (0, 0) is the image's top-left corner: a quad whose
// top corners have v = 0 shows the image's top half at its top.
TEST(GltfTexture, TheImageIsTheRightWayUp) {
  const auto dir = test::scratch_dir();
  Image stripes(8, 8);  // red in the top half, blue in the bottom half
  for (int y = 0; y < stripes.height; ++y)
    for (int x = 0; x < stripes.width; ++x) stripes.at(x, y, y < stripes.height / 2 ? 0 : 2) = 1.0f;
  write_image(dir / "stripes.png", stripes, {});

  test::GltfFile gltf;
  // Top-left, bottom-left, bottom-right and top-right corners of a quad facing +z.
  const int positions = gltf.floats({-1, 1, 0, -1, -1, 0, 1, -1, 0, 1, 1, 0}, "VEC3");
  const int uvs = gltf.floats({0, 0, 0, 1, 1, 1, 1, 0}, "VEC2");
  const int quad = gltf.mesh(positions, gltf.indices({1, 2, 3, 1, 3, 0}));
  nlohmann::json& primitive = gltf.json["meshes"][quad]["primitives"][0];
  primitive["attributes"]["TEXCOORD_0"] = uvs;
  primitive["material"] = 0;
  gltf.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}}}};
  gltf.json["textures"] = {{{"source", 0}}};
  gltf.json["images"] = {{{"uri", "stripes.png"}}};
  gltf.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.0}, {"znear", 0.1}}}}};
  gltf.scene({gltf.node({{"mesh", quad}}), gltf.node({{"camera", 0}, {"translation", {0, 0, 3}}})});
  const auto scene = gltf.write("quad");

  const auto out = dir / "quad.exr";
  test::run_rtpro("render " + scene.string() + " -o " + out.string() + " --size 32x32 --spp 4 -q", 0);
  const Image image = read_image(out);
  // The camera looks straight at the quad, which fills the middle 80% of the picture.
  const int x = image.width / 2;
  const int top = image.height / 4, bottom = 3 * image.height / 4;
  EXPECT_GT(image.at(x, top, 0), 2.0f * image.at(x, top, 2)) << "the top of the picture is not red";
  EXPECT_GT(image.at(x, bottom, 2), 2.0f * image.at(x, bottom, 0)) << "the bottom of the picture is not blue";
}

}  // namespace gltf_texture_test
}  // namespace rtpro
