// glTF samplers through the real binary: a quad whose texture coordinates run from -1 to 2 shows
// a 2x2 texture wrapped as its sampler's wrapS and wrapT say, each axis its own way, and with
// magFilter NEAREST each texel's own value. The quad emits its texture (emissiveTexture, black
// base colour), so a pixel is the texel it sees.
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace rtpro {
namespace gltf_sampler_test {

constexpr int kRepeat = 10497, kMirror = 33648, kClamp = 33071, kNearest = 9728;

// A 2x2 float image whose red is its texel's column and blue its row.
void write_quadrants(const std::filesystem::path& file) {
  Image image(2, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      image.at(x, y, 0) = float(x);
      image.at(x, y, 2) = float(y);
    }
  write_image(file, image, {});
}

// A quad filling a square view exactly, its texture coordinates from -1 to 2 along both axes
// (three tiles; v down the picture, as glTF has it), emitting quadrants.exr through `sampler`.
std::filesystem::path sampled_quad(const std::string& name, const nlohmann::json& sampler) {
  test::GltfFile gltf;
  const int positions = gltf.floats({-1, 1, 0, -1, -1, 0, 1, -1, 0, 1, 1, 0}, "VEC3");
  const int uvs = gltf.floats({-1, -1, -1, 2, 2, 2, 2, -1}, "VEC2");
  const int quad = gltf.mesh(positions, gltf.indices({1, 2, 3, 1, 3, 0}));
  nlohmann::json& primitive = gltf.json["meshes"][quad]["primitives"][0];
  primitive["attributes"]["TEXCOORD_0"] = uvs;
  primitive["material"] = 0;
  gltf.json["materials"] = nlohmann::json::array();
  gltf.json["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}}},
                                    {"emissiveFactor", {1, 1, 1}},
                                    {"emissiveTexture", {{"index", 0}}}});
  gltf.json["samplers"] = nlohmann::json::array();
  gltf.json["samplers"].push_back(sampler);
  gltf.json["textures"] = nlohmann::json::array();
  gltf.json["textures"].push_back({{"source", 0}, {"sampler", 0}});
  gltf.json["images"] = nlohmann::json::array();
  gltf.json["images"].push_back({{"uri", "quadrants.exr"}});
  // yfov 0.8 from 1 / tan(0.4) away: the view's edges are the quad's.
  gltf.json["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.0}, {"znear", 0.1}}}}};
  gltf.scene({gltf.node({{"mesh", quad}}), gltf.node({{"camera", 0}, {"translation", {0, 0, 1 / std::tan(0.4)}}})});
  write_quadrants(test::scratch_dir() / "quadrants.exr");
  return gltf.write(name);
}

// The texel each of the six half-tile bands shows (0 or 1, read from `channel` at the bands'
// centres along x for red, along y for blue); -1 where a pixel is a blend.
std::vector<int> bands(const Image& image, int channel) {
  std::vector<int> texels;
  for (int band = 0; band < 6; ++band) {
    const int at = 4 * band + 2;
    const float value = channel == 0 ? image.at(at, 12, 0) : image.at(12, at, 2);
    texels.push_back(value > 0.99f && value < 1.01f ? 1 : std::fabs(value) < 0.01f ? 0 : -1);
  }
  return texels;
}

Image render(const std::filesystem::path& scene, const std::string& backend) {
  const auto out = scene.parent_path() / (scene.stem().string() + "_" + backend + ".exr");
  test::run_rtpro(test::render_args(scene, out) + " --size 24x24 --spp 4 -q --backend " + backend, 0);
  return read_image(out);
}

TEST(GltfSampler, EachAxisWrapsAsItsSamplerSaysWithNearestTexels) {
  const auto mirror_clamp =
      sampled_quad("mirror_clamp", {{"wrapS", kMirror}, {"wrapT", kClamp}, {"magFilter", kNearest}});
  for (const std::string backend : {"native", "embree"}) {
    SCOPED_TRACE(backend);
    const Image image = render(mirror_clamp, backend);
    // u from -1 to 2 by half tiles: mirrored 1 0 | 0 1 | 1 0; clamped 0 0 | 0 1 | 1 1.
    EXPECT_EQ(bands(image, 0), (std::vector<int>{1, 0, 0, 1, 1, 0}));
    EXPECT_EQ(bands(image, 2), (std::vector<int>{0, 0, 0, 1, 1, 1}));
  }
  const Image repeat_mirror = render(
      sampled_quad("repeat_mirror", {{"wrapS", kRepeat}, {"wrapT", kMirror}, {"magFilter", kNearest}}), "embree");
  EXPECT_EQ(bands(repeat_mirror, 0), (std::vector<int>{0, 1, 0, 1, 0, 1}));
  EXPECT_EQ(bands(repeat_mirror, 2), (std::vector<int>{1, 0, 0, 1, 1, 0}));
}

// Without magFilter NEAREST the texels are blended: column 12 sees u from 0.5 to 0.625, between
// the texel centres 0.25 (red 0) and 0.75 (red 1), where bilinear filtering gives 0.625 on average
// and the nearest texel would be 1.
TEST(GltfSampler, LinearFilteringBlendsNeighbouringTexels) {
  const Image image = render(sampled_quad("linear", {{"wrapS", kClamp}, {"wrapT", kClamp}}), "embree");
  EXPECT_NEAR(image.at(12, 12, 0), 0.625f, 0.05f);
}

// A wrap mode glTF does not define is refused at its JSON path.
TEST(GltfSampler, AnUndefinedWrapModeIsRefusedAtItsPath) {
  const auto scene = sampled_quad("undefined", {{"wrapS", 1234}});
  test::expect_rtpro_answer(test::render_args(scene, scene.parent_path() / "undefined.exr", "-q"), 2,
                            "samplers[0].wrapS: 1234 is not one of 33071 (CLAMP_TO_EDGE)");
}

}  // namespace gltf_sampler_test
}  // namespace rtpro
