// The glTF texture slots on a hand-made quad, through the real binary: the base colour image is the
// right way up, normalTexture bends the shading normal along the surface's texture axes, metallicRoughnessTexture scales the roughness
// and metalness factors, and emissiveTexture colours what a surface emits, both where a path hits
// it and where light sampling picks a point on it.
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace rtpro {
namespace gltf_texture_slots_test {

using test::render_args;

// An 8×8 float image of one colour in the test's scratch folder (EXR: written as it is, where a
// PNG would be encoded for display; the data slots decode their images as "Raw").
std::filesystem::path solid_texture(const std::string& name, float r, float g, float b) {
  Image image(8, 8);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      image.at(x, y, 0) = r;
      image.at(x, y, 1) = g;
      image.at(x, y, 2) = b;
    }
  const auto file = test::write_file(name, "");
  write_image(file, image, {});
  return file;
}

// A quad of side 2 facing +z at the origin, its top corners at v = 0 as glTF has it (u grows along
// +x, v down along −y), with `material`; a camera 3 units in front of it; and, unless `light` is
// null, a directional light travelling against `from_light` (unit; from the front).
std::filesystem::path quad_scene(const std::string& name, const nlohmann::json& material,
                                 const std::vector<std::string>& image_uris, const Vec3* from_light) {
  test::GltfFile gltf;
  const int positions = gltf.floats({-1, 1, 0, -1, -1, 0, 1, -1, 0, 1, 1, 0}, "VEC3");
  const int uvs = gltf.floats({0, 0, 0, 1, 1, 1, 1, 0}, "VEC2");
  const int quad = gltf.mesh(positions, gltf.indices({1, 2, 3, 1, 3, 0}));
  nlohmann::json& primitive = gltf.json["meshes"][quad]["primitives"][0];
  primitive["attributes"]["TEXCOORD_0"] = uvs;
  primitive["material"] = 0;
  // Arrays built element by element: a braced list of one json value is that value to some
  // compilers and a one-element array to others.
  gltf.json["materials"] = nlohmann::json::array();
  gltf.json["materials"].push_back(material);
  gltf.json["textures"] = nlohmann::json::array();
  gltf.json["images"] = nlohmann::json::array();
  for (std::size_t i = 0; i < image_uris.size(); ++i) {
    gltf.json["textures"].push_back(nlohmann::json::object({{"source", i}}));
    gltf.json["images"].push_back(nlohmann::json::object({{"uri", image_uris[i]}}));
  }
  gltf.json["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"aspectRatio", 1.0}, {"znear", 0.1}}}}};
  std::vector<int> roots{gltf.node({{"mesh", quad}}), gltf.node({{"camera", 0}, {"translation", {0, 0, 3}}})};
  if (from_light) {
    gltf.json["extensionsUsed"] = {"KHR_lights_punctual"};
    gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}, {"intensity", 683.0}}};
    // A directional light shines along its node's −z: rotate +z onto from_light (a turn about the
    // axis z × from_light).
    const Vec3 z(0.0f, 0.0f, 1.0f);
    const Vec3 axis = cross(z, *from_light);
    const float sin_angle = length(axis), cos_angle = dot(z, *from_light);
    const float half = 0.5f * std::atan2(sin_angle, cos_angle);
    const Vec3 unit_axis = sin_angle > 0.0f ? axis / sin_angle : Vec3(1.0f, 0.0f, 0.0f);
    const Vec3 q = unit_axis * std::sin(half);
    roots.push_back(gltf.node(
        {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"rotation", {q.x, q.y, q.z, std::cos(half)}}}));
  }
  gltf.scene(roots);
  return gltf.write(name);
}

// The mean of channel c over the middle half of the picture (all quad).
double centre_mean(const Image& image, int c) {
  double sum = 0.0;
  int n = 0;
  for (int y = image.height / 4; y < 3 * image.height / 4; ++y)
    for (int x = image.width / 4; x < 3 * image.width / 4; ++x, ++n) sum += image.at(x, y, c);
  return sum / n;
}

// Into NAME.render.exr: NAME.exr may be the scene's own texture, which rtpro refuses to replace.
Image render(const std::filesystem::path& scene, const std::string& options = "--spp 16") {
  const auto out = scene.parent_path() / (scene.stem().string() + ".render.exr");
  test::run_rtpro(render_args(scene, out) + " --size 24x24 -q " + options, 0);
  return read_image(out);
}

// A white Lambertian surface (KHR_materials_specular with specularFactor 0 leaves the pure base).
nlohmann::json lambert(nlohmann::json extra = nlohmann::json::object()) {
  nlohmann::json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}}},
                      {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0}}}}}};
  m.update(extra);
  return m;
}

// A normal map texel (in [0, 1]) of the normal tilted by `degrees` towards +u, or towards +v on
// the image (its top) when `along_v`.
std::filesystem::path tilted_normal(const std::string& name, float degrees, bool along_v) {
  const float s = std::sin(degrees * 3.14159265f / 180.0f), c = std::cos(degrees * 3.14159265f / 180.0f);
  return along_v ? solid_texture(name, 0.5f, 0.5f + 0.5f * s, 0.5f + 0.5f * c)
                 : solid_texture(name, 0.5f + 0.5f * s, 0.5f, 0.5f + 0.5f * c);
}

// An image red in its top half and blue in its bottom half, in the test's scratch folder.
void write_stripes(const std::filesystem::path& file) {
  Image stripes(8, 8);
  for (int y = 0; y < stripes.height; ++y)
    for (int x = 0; x < stripes.width; ++x) stripes.at(x, y, y < stripes.height / 2 ? 0 : 2) = 1.0f;
  write_image(file, stripes, {});
}

// By the glTF specification texture coordinate (0, 0) is the image's top-left corner: the quad,
// whose top corners have v = 0, shows the image's top half at its top.
TEST(GltfTextureSlots, TheBaseColourImageIsTheRightWayUp) {
  write_stripes(test::scratch_dir() / "stripes.png");
  const nlohmann::json material = {
      {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}}};
  const Image image = render(quad_scene("quad", material, {"stripes.png"}, nullptr), "--spp 4");
  const int x = image.width / 2, top = image.height / 4, bottom = 3 * image.height / 4;
  EXPECT_GT(image.at(x, top, 0), 2.0f * image.at(x, top, 2)) << "the top of the picture is not red";
  EXPECT_GT(image.at(x, bottom, 2), 2.0f * image.at(x, bottom, 0)) << "the bottom of the picture is not blue";
}

TEST(GltfTextureSlots, ANormalMapTiltsTheShadingTowardsItsTextureAxes) {
  test::scratch_dir();
  const float k = std::sqrt(0.5f);
  const Vec3 from_right(k, 0.0f, k), from_above(0.0f, k, k);
  const auto brightness = [&](const std::string& name, float degrees, bool along_v, const Vec3& light) {
    tilted_normal(name + ".exr", degrees, along_v);
    const nlohmann::json material = lambert({{"normalTexture", {{"index", 0}}}});
    return centre_mean(render(quad_scene(name, material, {name + ".exr"}, &light)), 1);
  };
  // Lambert under a light 45° off the normal: cos 45° flat, cos 15° tilted 30° towards the light,
  // cos 75° tilted away.
  const double flat = brightness("flat", 0.0f, false, from_right);
  ASSERT_GT(flat, 0.0);
  EXPECT_NEAR(brightness("towards_u", 30.0f, false, from_right) / flat, std::cos(0.2618) / std::cos(0.7854), 0.05);
  EXPECT_NEAR(brightness("away_u", -30.0f, false, from_right) / flat, std::cos(1.309) / std::cos(0.7854), 0.05);
  // +y of the map is the image's up, where the quad's top is.
  EXPECT_NEAR(brightness("towards_v", 30.0f, true, from_above) / flat, std::cos(0.2618) / std::cos(0.7854), 0.05);
  // The map's scale multiplies its x and y: 0 undoes the tilt.
  tilted_normal("scaled.exr", 30.0f, false);
  const nlohmann::json unscaled = lambert({{"normalTexture", {{"index", 0}, {"scale", 0.0}}}});
  EXPECT_NEAR(centre_mean(render(quad_scene("scaled", unscaled, {"scaled.exr"}, &from_right)), 1) / flat, 1.0, 0.01)
      << "scale 0 leaves the map's z alone, which normalises to the flat normal";
}

TEST(GltfTextureSlots, MetallicRoughnessTextureScalesTheFactors) {
  test::scratch_dir();
  const float k = std::sqrt(0.5f);
  const Vec3 light(k, 0.0f, k);
  const auto red = [](float metallic, float roughness) {
    return nlohmann::json{
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {0.8, 0.1, 0.1, 1}}, {"metallicFactor", metallic}, {"roughnessFactor", roughness}}}};
  };
  // Green 0.5 (roughness) and blue 0 or 1 (metalness), under factors of 1.
  solid_texture("dielectric.exr", 0.0f, 0.5f, 0.0f);
  solid_texture("metal.exr", 0.0f, 0.5f, 1.0f);
  nlohmann::json textured = red(1.0f, 1.0f);
  textured["pbrMetallicRoughness"]["metallicRoughnessTexture"] = {{"index", 0}};
  const Image from_dielectric_texture = render(quad_scene("t_dielectric", textured, {"dielectric.exr"}, &light));
  const Image from_metal_texture = render(quad_scene("t_metal", textured, {"metal.exr"}, &light));
  const Image dielectric = render(quad_scene("dielectric", red(0.0f, 0.5f), {}, &light));
  const Image metal = render(quad_scene("metal", red(1.0f, 0.5f), {}, &light));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(centre_mean(from_dielectric_texture, c), centre_mean(dielectric, c),
                0.01 * centre_mean(dielectric, c) + 1e-4)
        << "channel " << c;
    EXPECT_NEAR(centre_mean(from_metal_texture, c), centre_mean(metal, c), 0.01 * centre_mean(metal, c) + 1e-4)
        << "channel " << c;
  }
  // And the two differ, so the comparison says something.
  EXPECT_GT(std::fabs(centre_mean(dielectric, 0) - centre_mean(metal, 0)), 0.1 * centre_mean(dielectric, 0));
}

TEST(GltfTextureSlots, TheEmissiveTextureColoursTheEmissionSeenAndSampled) {
  const auto dir = test::scratch_dir();
  write_stripes(dir / "stripes.png");
  nlohmann::json emitter = {{"pbrMetallicRoughness", {{"baseColorFactor", {0, 0, 0, 1}}, {"metallicFactor", 0}}},
                            {"emissiveFactor", {1, 1, 1}},
                            {"emissiveTexture", {{"index", 0}}}};
  const Image seen = render(quad_scene("emitter", emitter, {"stripes.png"}, nullptr), "--spp 4");
  const int x = seen.width / 2, top = seen.height / 4, bottom = 3 * seen.height / 4;
  EXPECT_GT(seen.at(x, top, 0), 0.5f);
  EXPECT_LT(seen.at(x, top, 2), 0.05f);
  EXPECT_GT(seen.at(x, bottom, 2), 0.5f);
  EXPECT_LT(seen.at(x, bottom, 0), 0.05f);

  // The same emitter turned to face down 1 above a white floor (its red half towards the camera):
  // light sampling, which picks points on it and evaluates its texture there, and BSDF sampling,
  // which hits it, give one mean per channel.
  test::write_file("floor.obj", "v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\nf 1 4 3 2\n");
  const auto mean_with = [&](const char* sampling) {
    const auto scene = test::write_file(std::string("floor_") + sampling + ".yaml", std::string(R"(rtpro: 1
camera: {position: [0, 0.4, 3], look_at: [0, 0.2, 0], fov: 60, resolution: [24, 24]}
render: {integrator: path, spp: 256, max_depth: 2, sampling: )") + sampling + R"(}
materials:
  floor: {type: diffuse, color: [1, 1, 1]}
objects:
  emitter: [{type: mesh, file: emitter.gltf}]
world:
  - {type: mesh, file: floor.obj, material: floor}
  - {type: instance, object: emitter, transform: {translate: [0, 1, 0], rotate: {axis: [1, 0, 0], angle: 90}}}
)");
    const auto out = dir / (std::string("floor_") + sampling + ".exr");
    test::run_rtpro(render_args(scene, out, "-q"), 0);
    const Image image = read_image(out);
    // The floor only: the bottom third of the picture.
    std::array<double, 3> mean{};
    int n = 0;
    for (int y = 2 * image.height / 3; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x, ++n)
        for (int c = 0; c < 3; ++c) mean[c] += image.at(x, y, c);
    for (double& m : mean) m /= n;
    return mean;
  };
  const std::array<double, 3> light = mean_with("light"), bsdf = mean_with("bsdf");
  for (int c = 0; c < 3; c += 2) {
    EXPECT_GT(light[c], 1e-3) << "channel " << c;
    EXPECT_NEAR(light[c], bsdf[c], 0.05 * bsdf[c]) << "channel " << c;
  }
  EXPECT_LT(light[1], 0.01 * light[0]) << "the stripes have no green";
}

}  // namespace gltf_texture_slots_test
}  // namespace rtpro
