// Material kinds in the scene file (`type:`), emission, and the path integrator's render keys:
// what each reads, and the errors that name the key and its position.
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace material_kinds_test {

using test::kHeader;

SceneDescription parse(const std::string& body, const std::vector<std::string>& overrides = {}) {
  return parse_scene_text(kHeader + body, "test.yaml", overrides);
}

std::string error_of(const std::string& body) {
  try {
    parse(body);
  } catch (const InputError& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(MaterialKinds, EachTypeReadsItsOwnKeys) {
  const SceneDescription d = parse(R"(materials:
  wall: {type: diffuse, color: [0.5, 0.4, 0.3]}
  gold: {type: conductor, color: [1, 0.78, 0.34], roughness: 0.3}
  copper: {type: conductor, eta: [0.2, 0.92, 1.1], k: [3.9, 2.45, 2.14]}
  glass: {type: dielectric, roughness: 0.1}
  lamp: {type: diffuse, color: [0, 0, 0], emission: [17, 12, 4], emission_strength: 2, emission_sides: both}
  old: {color: [0.9, 0.1, 0.1], reflectivity: 0.3}
)");
  ASSERT_EQ(d.materials.size(), 7u);
  EXPECT_TRUE(std::holds_alternative<DiffuseParams>(d.materials[1].params));
  const auto& gold = std::get<ConductorParams>(d.materials[2].params);
  EXPECT_FLOAT_EQ(gold.roughness, 0.3f);
  EXPECT_FALSE(gold.eta);
  const auto& copper = std::get<ConductorParams>(d.materials[3].params);
  ASSERT_TRUE(copper.k);
  EXPECT_FLOAT_EQ(copper.k->y, 2.45f);
  const auto& glass = std::get<DielectricParams>(d.materials[4].params);
  EXPECT_FLOAT_EQ(glass.roughness, 0.1f);
  EXPECT_FLOAT_EQ(glass.glass.ior, 1.5f);                         // a dielectric's default index
  EXPECT_EQ(d.materials[5].emission, Color(34.0f, 24.0f, 8.0f));  // radiance: values above 1 are meant
  EXPECT_TRUE(d.materials[5].emission_two_sided);
  EXPECT_TRUE(std::holds_alternative<PhongParams>(d.materials[6].params));
}

TEST(MaterialKinds, TheRenderSceneCarriesTheModelAndAWhittedApproximation) {
  const RenderScene scene = build_render_scene(parse(R"(materials:
  wall: {type: diffuse, color: [0.5, 0.4, 0.3]}
  mirror: {type: conductor, color: [0.9, 0.9, 0.9]}
  lamp: {type: diffuse, emission: [2, 2, 2]}
)"));
  ASSERT_EQ(scene.materials.size(), 4u);
  EXPECT_TRUE(std::holds_alternative<PhongSurface>(scene.materials[0].model));
  EXPECT_TRUE(std::holds_alternative<DiffuseSurface>(scene.materials[1].model));
  EXPECT_EQ(scene.materials[1].whitted.specular, 0.0f);
  EXPECT_EQ(std::get<Color>(scene.materials[1].base_color), Color(0.5f, 0.4f, 0.3f));
  ASSERT_TRUE(std::holds_alternative<ConductorSurface>(scene.materials[2].model));
  EXPECT_EQ(scene.materials[2].whitted.reflectivity, 1.0f);  // a smooth conductor is a mirror under whitted
  EXPECT_TRUE(scene.materials[3].emission.emits());
  EXPECT_FALSE(scene.materials[3].emission.two_sided);
  EXPECT_FALSE(scene.materials[0].emission.emits());
}

// The medium a path inside the surface travels through is the kind's own, not its Whitted glass.
TEST(MaterialKinds, EachKindSaysWhatItsInsideAbsorbs) {
  const RenderScene scene = build_render_scene(parse(R"(materials:
  water: {type: dielectric, ior: 1.33, transmittance: [0.5, 0.8, 0.9], transmittance_distance: 2}
  crystal: {ior: 1.6}
  wall: {type: diffuse}
  glass: {type: principled, transmission_weight: 1}
)"));
  ASSERT_EQ(scene.materials.size(), 5u);
  const Dielectric* water = interior_of(scene.materials[1]);
  ASSERT_NE(water, nullptr);
  EXPECT_FLOAT_EQ(water->ior, 1.33f);
  EXPECT_EQ(water->transmittance, Color(0.5f, 0.8f, 0.9f));
  EXPECT_FLOAT_EQ(water->transmittance_distance, 2.0f);
  ASSERT_NE(interior_of(scene.materials[2]), nullptr);  // a Phong material with an index is glass
  EXPECT_FLOAT_EQ(interior_of(scene.materials[2])->ior, 1.6f);
  EXPECT_EQ(interior_of(scene.materials[0]), nullptr);  // the default material
  EXPECT_EQ(interior_of(scene.materials[3]), nullptr);
  EXPECT_EQ(interior_of(scene.materials[4]), nullptr);
}

TEST(MaterialKinds, PrincipledReadsTheGltfModelsParameters) {
  const SceneDescription d = parse(R"(materials:
  car_paint: {type: principled, color: [0.6, 0.05, 0.05], metalness: 0.2, roughness: 0.4, coat_weight: 1, coat_roughness: 0.05}
  velvet: {type: principled, fuzz_color: [1, 0.5, 0.5], fuzz_roughness: 0.3, specular_weight: 0}
  glass: {type: principled, transmission_weight: 1, roughness: 0, ior: 1.45, specular_color: [1, 0.9, 0.8]}
)");
  ASSERT_TRUE(std::holds_alternative<PrincipledParams>(d.materials[1].params));
  const auto& paint = std::get<PrincipledParams>(d.materials[1].params);
  EXPECT_FLOAT_EQ(paint.metalness, 0.2f);
  EXPECT_FLOAT_EQ(paint.roughness, 0.4f);
  EXPECT_FLOAT_EQ(paint.coat_weight, 1.0f);
  const auto& velvet = std::get<PrincipledParams>(d.materials[2].params);
  EXPECT_FLOAT_EQ(velvet.roughness, 0.5f);  // the principled default
  EXPECT_EQ(velvet.fuzz_color, Color(1.0f, 0.5f, 0.5f));
  EXPECT_FLOAT_EQ(velvet.specular_weight, 0.0f);
  const auto& glass = std::get<PrincipledParams>(d.materials[3].params);
  EXPECT_FLOAT_EQ(glass.ior, 1.45f);
  EXPECT_FLOAT_EQ(glass.transmission_weight, 1.0f);
  const RenderScene scene = build_render_scene(d);
  const auto& model = std::get<PrincipledSurface>(scene.materials[3].model);
  EXPECT_FLOAT_EQ(model.ior, 1.45f);
  EXPECT_FALSE(scene.materials[3].whitted.glass);  // no Whitted glass: its transmission is the model's own
  EXPECT_NE(error_of("materials:\n  m: {type: principled, metalness: 2}\n").find("from 0 to 1"), std::string::npos);
  EXPECT_NE(error_of("materials:\n  m: {type: principled, eta: [1, 1, 1], k: [1, 1, 1]}\n").find("unknown key 'eta'"),
            std::string::npos);
}

TEST(MaterialKinds, AKeyOfAnotherKindIsAnErrorAtItsPosition) {
  const std::string error = error_of("materials:\n  gold: {type: conductor, reflectivity: 0.5}\n");
  EXPECT_NE(error.find("test.yaml:4:"), std::string::npos) << error;
  EXPECT_NE(error.find("unknown key 'reflectivity' in material 'gold'"), std::string::npos) << error;
}

TEST(MaterialKinds, BadValuesAreErrors) {
  EXPECT_NE(error_of("materials:\n  m: {type: metal}\n")
                .find("must be phong, diffuse, conductor, dielectric, principled, hair or interface"),
            std::string::npos);
  EXPECT_NE(error_of("materials:\n  m: {type: conductor, roughness: 1.5}\n").find("from 0 (smooth) to 1"),
            std::string::npos);
  EXPECT_NE(error_of("materials:\n  m: {type: conductor, eta: [1, 1, 1]}\n").find("needs both eta and k"),
            std::string::npos);
  EXPECT_NE(error_of("materials:\n  m: {emission: [-1, 0, 0]}\n").find("each channel 0 or more"), std::string::npos);
  EXPECT_NE(error_of("materials:\n  m: {emission_strength: 2}\n").find("give the material an emission colour"),
            std::string::npos);
  EXPECT_NE(error_of("materials:\n  m: {emission: [1, 1, 1], emission_sides: back}\n").find("front or both"),
            std::string::npos);
}

TEST(MaterialKinds, RenderIntegratorAndSamplingAreReadAndChecked) {
  const SceneDescription d = parse("render: {integrator: path, sampling: light}\n");
  EXPECT_EQ(d.render.integrator, Integrator::kPath);
  EXPECT_EQ(d.render.path_sampling, PathSampling::kLight);
  EXPECT_EQ(parse("").render.integrator, Integrator::kWhitted);
  EXPECT_EQ(parse("", {"render.integrator=path"}).render.integrator, Integrator::kPath);
  EXPECT_NE(error_of("render: {integrator: bdpt}\n").find("must be path or whitted"), std::string::npos);
  EXPECT_NE(error_of("render: {sampling: both}\n").find("must be mis, light or bsdf"), std::string::npos);
}

}  // namespace material_kinds_test
}  // namespace rtpro
