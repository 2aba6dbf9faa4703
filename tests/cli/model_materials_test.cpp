// `--set materials.NAME.KEY=VALUE` on a model file read as the whole scene reaches the model's own
// material NAME: the keys given change, the file's other values (its textures among them) stay,
// and a name the model does not have is refused at the override with the nearest name.
#include "rtpro/image/image_io.h"
#include "scene/gltf_test_files.h"
#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace model_materials_test {

using test::render_args;

// A quad facing the camera of the file, in material "Paint" (white, rough, not metal), lit from
// the front by a directional light.
std::filesystem::path painted_quad() {
  test::GltfFile gltf;
  const int quad =
      gltf.mesh(gltf.floats({-1, 1, 0, -1, -1, 0, 1, -1, 0, 1, 1, 0}, "VEC3"), gltf.indices({1, 2, 3, 1, 3, 0}));
  gltf.json["meshes"][quad]["primitives"][0]["material"] = 0;
  gltf.json["materials"] = nlohmann::json::array();
  gltf.json["materials"].push_back(
      {{"name", "Paint"}, {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 0}}}});
  gltf.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"] = nlohmann::json::array();
  gltf.json["extensions"]["KHR_lights_punctual"]["lights"].push_back({{"type", "directional"}, {"intensity", 683.0}});
  gltf.node({{"mesh", quad}});
  gltf.node({{"camera", 0}, {"translation", {0, 0, 3}}});
  gltf.node({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 0, 1}}});
  gltf.scene({0, 1, 2});
  return gltf.write("paint");
}

TEST(ModelMaterials, SetReachesAGltfMaterialByName) {
  const auto dir = test::scratch_dir();
  const auto model = painted_quad();
  test::run_rtpro(render_args(model, dir / "white.exr", "-q --size 8x8 --spp 1"), 0);
  test::run_rtpro(render_args(model, dir / "red.exr", "-q --size 8x8 --spp 1 --set materials.Paint.color=[1,0,0]"), 0);
  const Image white = read_image(dir / "white.exr"), red = read_image(dir / "red.exr");
  // Red keeps the white's red; of green and blue only the untinted specular layer's few percent.
  EXPECT_GT(white.at(4, 4, 1), 0.05f);
  EXPECT_NEAR(red.at(4, 4, 0), white.at(4, 4, 0), 1e-6f);
  EXPECT_LT(red.at(4, 4, 1), 0.1f * white.at(4, 4, 1));
  EXPECT_LT(red.at(4, 4, 2), 0.1f * white.at(4, 4, 2));
  test::expect_rtpro_answer("info " + model.string() + " --set materials.Pant.color=[1,0,0]", 2,
                            "--set materials.Pant.color=[1,0,0]: paint.gltf has no material 'Pant'; did you mean "
                            "'Paint'? (its materials: default, Paint)");
  // A new material that a shape uses is not a misspelt name: the whole model in clay.
  test::run_rtpro(render_args(model, dir / "clay.exr",
                              "-q --size 8x8 --spp 1 --set 'materials.clay={type: diffuse, color: [0, 0, 1]}' "
                              "--set world.0.material=clay"),
                  0);
  const Image clay = read_image(dir / "clay.exr");
  EXPECT_EQ(clay.at(4, 4, 0), 0.0f);
  EXPECT_GT(clay.at(4, 4, 2), 0.05f);
}

}  // namespace model_materials_test
}  // namespace rtpro
