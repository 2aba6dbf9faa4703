// Where media live in a scene: a material's and an entry's `interior:`, the world's `medium:`, a
// glass's transmittance as an absorbing medium, interfaces, and the values each is read into.
#include "gltf_asset.h"
#include "gltf_loader.h"
#include "gltf_test_files.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace rtpro {
namespace medium_scene_test {

using test::check_error;
using test::kHeader;

RenderScene build(const std::string& body) {
  return build_render_scene(parse_scene_text(kHeader + body, "test.yaml", {}));
}

const HomogeneousMedium& homogeneous(const RenderScene& scene, MediumIndex medium) {
  return std::get<HomogeneousMedium>(scene.media.at(medium));
}

TEST(MediumScene, InteriorsTheWorldAndInterfaces) {
  const RenderScene scene = build(R"(medium: {color: [0.5, 1, 1], density: 0.2, anisotropy: -0.3}
materials:
  fog: {type: interface, interior: {sigma_a: [0.1, 0.2, 0.3], sigma_s: [1, 2, 3], anisotropy: 0.5, emission: [0, 1, 0]}}
  hole: {type: interface}
  wall: {type: diffuse}
world:
  - {type: sphere, material: fog}
  - {type: sphere, material: wall, interior: {sigma_s: [4, 4, 4]}}
)");
  const HomogeneousMedium& world = homogeneous(scene, scene.world_medium);
  EXPECT_EQ(world.sigma_s, Color(0.1f, 0.2f, 0.2f));
  EXPECT_EQ(world.sigma_a, Color(0.1f, 0.0f, 0.0f));
  EXPECT_FLOAT_EQ(world.anisotropy, -0.3f);
  const Material& fog = scene.materials[1];
  EXPECT_TRUE(fog.index_matched);
  ASSERT_TRUE(fog.interior.has_value());
  EXPECT_EQ(homogeneous(scene, *fog.interior).sigma_s, Color(1.0f, 2.0f, 3.0f));
  EXPECT_EQ(homogeneous(scene, *fog.interior).emission, Color(0.0f, 1.0f, 0.0f));
  EXPECT_EQ(scene.materials[2].interior, kNoMedium);      // an interface without interior: vacuum
  EXPECT_FALSE(scene.materials[3].interior.has_value());  // a wall bounds nothing
  // The entry's interior is a copy of its material with that inside.
  ASSERT_EQ(scene.material_names.back(), "wall+interior");
  EXPECT_EQ(homogeneous(scene, *scene.materials.back().interior).sigma_s, Color(4.0f));
  EXPECT_EQ(std::get<SphereSet>(scene.top.geometries[0]).spheres[1].material, scene.materials.size() - 1);
}

TEST(MediumScene, GlassTransmittanceIsAnAbsorbingInterior) {
  const RenderScene scene = build(R"(materials:
  green: {type: dielectric, transmittance: [0.5, 1, 0], transmittance_distance: 2}
  clear: {type: dielectric}
)");
  const auto& green = std::get<AbsorbingMedium>(scene.media.at(*scene.materials[1].interior));
  EXPECT_EQ(green.transmittance, Color(0.5f, 1.0f, 0.0f));
  EXPECT_EQ(green.distance, 2.0f);
  EXPECT_EQ(scene.materials[2].interior, kNoMedium);  // clear glass holds vacuum, not the world's fog
}

TEST(MediumScene, WhittedSeesAGlassInteriorAsAbsorption) {
  const RenderScene scene = build(R"(materials:
  juice: {type: dielectric, ior: 1.33, interior: {sigma_a: [0.5, 0, 0], sigma_s: [0, 1, 0]}}
)");
  const Color kept = scene.materials[1].whitted.glass->transmittance;
  EXPECT_FLOAT_EQ(kept.x, std::exp(-0.5f));
  EXPECT_FLOAT_EQ(kept.y, std::exp(-1.0f));
  EXPECT_EQ(kept.z, 1.0f);
}

TEST(MediumScene, GltfVolumeIsAnAbsorbingInterior) {
  test::GltfFile gltf;
  gltf.json["extensionsUsed"] = {"KHR_materials_volume", "KHR_materials_transmission"};
  gltf.json["materials"] = {
      {{"name", "wine"},
       {"extensions",
        {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
         {"KHR_materials_volume",
          {{"thicknessFactor", 0.1}, {"attenuationDistance", 0.5}, {"attenuationColor", {0.5, 0.25, 1}}}}}}},
      {{"name", "thin"}, {"extensions", {{"KHR_materials_volume", {{"attenuationDistance", 0.5}}}}}},
      {{"name", "clear"}, {"extensions", {{"KHR_materials_volume", {{"thicknessFactor", 1}}}}}}};
  gltf.scene({gltf.node({{"mesh", gltf.mesh(gltf.floats(test::kTriangle, "VEC3"))}})});
  const GltfAsset asset = load_gltf_file(gltf.write("volume"));
  ASSERT_EQ(asset.materials.size(), 3u);
  ASSERT_TRUE(asset.materials[0].interior.has_value());
  const auto& wine = std::get<AbsorbingMedium>(*asset.materials[0].interior);
  EXPECT_EQ(wine.transmittance, Color(0.5f, 0.25f, 1.0f));
  EXPECT_EQ(wine.distance, 0.5f);
  EXPECT_FALSE(asset.materials[1].interior.has_value());  // thickness 0: a thin wall
  ASSERT_TRUE(asset.materials[2].interior.has_value());   // no attenuation: vacuum inside
  EXPECT_EQ(std::get<HomogeneousMedium>(*asset.materials[2].interior).sigma_a, Color(0.0f));
}

TEST(MediumScene, ErrorsPointAtTheValue) {
  const std::string glass =
      kHeader + "materials:\n  g: {type: dielectric, transmittance: [1, 1, 0.5], interior: {sigma_a: [1, 1, 1]}}\n";
  EXPECT_SCENE_ERROR(glass, test::at(glass, 4, "{sigma_a"), {"replaces the glass's transmittance"});
  const std::string negative = kHeader + "medium: {sigma_s: [1, -1, 1]}\n";
  EXPECT_SCENE_ERROR(negative, test::at(negative, 3, "[1, -1"), {"medium.sigma_s", "0 or more"});
  const std::string g = kHeader + "world:\n  - {type: sphere, interior: {sigma_s: [1, 1, 1], anisotropy: 1.0}}\n";
  EXPECT_SCENE_ERROR(g, test::at(g, 4, "1.0"), {"sphere.interior.anisotropy", "strictly between"});
  const std::string typo = kHeader + "medium: {sigma_s: [1, 1, 1], colour: [1, 1, 1]}\n";
  EXPECT_SCENE_ERROR(typo, test::at(typo, 3, "colour"), {"did you mean 'color'"});
}

}  // namespace medium_scene_test
}  // namespace rtpro
