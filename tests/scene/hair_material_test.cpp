// The hair material in a scene file (`type: hair`): its keys and defaults, its absorption from
// exactly one of sigma_a, melanin or color, the errors that name the key and its position, and
// what the render scene makes of it (the surface model and the Whitted approximation).
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/hair_absorption.h"
#include "rtpro/scene/scene_parser.h"
#include "scene_text_error.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace hair_material_test {

using test::at;
using test::kHeader;

SceneDescription parse(const std::string& materials) {
  return parse_scene_text(kHeader + "materials:\n" + materials, "test.yaml");
}

const HairParams& hair_of(const SceneDescription& d, std::size_t i) {
  return std::get<HairParams>(d.materials[i].params);
}

TEST(HairMaterial, ReadsEachKeyAndKeepsPbrtsDefaults) {
  const SceneDescription d = parse(R"(  plain: {type: hair, sigma_a: [0.06, 0.1, 0.2]}
  styled: {type: hair, melanin: 1.3, pheomelanin: 0.4, beta_m: 0.2, beta_n: 0.5, alpha: 3, ior: 1.6}
  dyed: {type: hair, color: [0.6, 0.3, 0.1], beta_n: 0.8}
)");
  const HairParams& plain = hair_of(d, 1);
  EXPECT_EQ(plain.absorption, HairAbsorption::kSigmaA);
  EXPECT_EQ(plain.sigma_a, Color(0.06f, 0.1f, 0.2f));
  EXPECT_FLOAT_EQ(plain.beta_m, 0.3f);
  EXPECT_FLOAT_EQ(plain.beta_n, 0.3f);
  EXPECT_FLOAT_EQ(plain.alpha_degrees, 2.0f);
  EXPECT_FLOAT_EQ(plain.ior, 1.55f);
  const HairParams& styled = hair_of(d, 2);
  EXPECT_EQ(styled.absorption, HairAbsorption::kMelanin);
  EXPECT_FLOAT_EQ(styled.eumelanin, 1.3f);
  EXPECT_FLOAT_EQ(styled.pheomelanin, 0.4f);
  EXPECT_FLOAT_EQ(styled.beta_m, 0.2f);
  EXPECT_FLOAT_EQ(styled.beta_n, 0.5f);
  EXPECT_FLOAT_EQ(styled.alpha_degrees, 3.0f);
  EXPECT_FLOAT_EQ(styled.ior, 1.6f);
  EXPECT_EQ(hair_of(d, 3).absorption, HairAbsorption::kColor);
  EXPECT_EQ(d.materials[3].color, Color(0.6f, 0.3f, 0.1f));
}

TEST(HairMaterial, TheRenderSceneWorksOutSigmaAAndAWhittedColour) {
  const RenderScene scene = build_render_scene(parse(R"(  brown: {type: hair, melanin: 1.3, pheomelanin: 0.2}
  dyed: {type: hair, color: [0.6, 0.3, 0.1], beta_n: 0.8}
)"));
  const HairSurface& brown = std::get<HairSurface>(scene.materials[1].model);
  EXPECT_FALSE(brown.sigma_a_from_color);
  const Color expected = hair_sigma_a_from_melanin(1.3f, 0.2f);
  EXPECT_EQ(brown.sigma_a, expected);
  // Red absorbed least: brown hair, and its Whitted colour shows it.
  const Color shown = std::get<Color>(scene.materials[1].whitted.color);
  EXPECT_GT(shown.x, shown.y);
  EXPECT_GT(shown.y, shown.z);
  EXPECT_EQ(shown, brown.color);
  EXPECT_EQ(scene.materials[1].whitted.reflectivity, 0.0f);
  const HairSurface& dyed = std::get<HairSurface>(scene.materials[2].model);
  EXPECT_TRUE(dyed.sigma_a_from_color);
  EXPECT_EQ(std::get<Color>(scene.materials[2].whitted.color), Color(0.6f, 0.3f, 0.1f));
  // The colour and σa are each other's inverse.
  const Color back = hair_color_from_sigma_a(hair_sigma_a_from_color(Color(0.6f, 0.3f, 0.1f), 0.8f), 0.8f);
  EXPECT_NEAR(back.x, 0.6f, 1e-5f);
  EXPECT_NEAR(back.z, 0.1f, 1e-5f);
}

TEST(HairMaterial, TheAbsorptionComesFromExactlyOneKey) {
  const std::string two = kHeader + "materials:\n  h: {type: hair, sigma_a: [1, 1, 1], melanin: 2}\n";
  EXPECT_SCENE_ERROR(two, at(two, 4, "2}"),
                     {"material 'h'.melanin", "one of sigma_a, melanin or color", "sigma_a is given"});
  const std::string coloured = kHeader + "materials:\n  h: {type: hair, melanin: 2, color: [0.5, 0.4, 0.3]}\n";
  EXPECT_SCENE_ERROR(coloured, at(coloured, 4, "[0.5"), {"material 'h'.color", "melanin is given"});
  const std::string none = kHeader + "materials:\n  h: {type: hair, beta_m: 0.2}\n";
  EXPECT_SCENE_ERROR(none, at(none, 4, "hair"), {"hair needs its absorption", "sigma_a: [r, g, b]", "melanin: m"});
  const std::string red = kHeader + "materials:\n  h: {type: hair, sigma_a: [1, 1, 1], pheomelanin: 2}\n";
  EXPECT_SCENE_ERROR(red, at(red, 4, "2}"), {"give melanin too"});
}

TEST(HairMaterial, OutOfRangeValuesAreErrorsAtTheirPosition) {
  struct Case {
    std::string entry, token, fragment;
  };
  const std::vector<Case> cases{
      {"{type: hair, melanin: 1, beta_m: 0}", "0}", "beta_m is a roughness above 0 and at most 1"},
      {"{type: hair, melanin: 1, beta_n: 1.5}", "1.5", "beta_n is a roughness above 0 and at most 1"},
      {"{type: hair, melanin: 1, beta_n: .nan}", ".nan", "beta_n"},
      {"{type: hair, melanin: 1, alpha: 120}", "120", "tilt in degrees, from -90 to 90"},
      {"{type: hair, melanin: 1, ior: 0.8}", "0.8", "1 or more (1.55 for keratin)"},
      {"{type: hair, sigma_a: [0.1, -1, 0.2]}", "[0.1", "each channel 0 or more"},
      {"{type: hair, sigma_a: [0.1, 1e40, 0.2]}", "1e40", "sigma_a"},
      {"{type: hair, melanin: -1}", "-1", "melanin must be >= 0"},
      {"{type: hair, color: [2, 0.5, 0.5]}", "[2", "reflectance"},
      {"{type: hair, melanin: 1, roughness: 0.5}", "roughness", "unknown key 'roughness'"},
  };
  for (const Case& c : cases) {
    const std::string text = kHeader + "materials:\n  h: " + c.entry + "\n";
    SCOPED_TRACE(c.entry);
    EXPECT_SCENE_ERROR(text, at(text, 4, c.token), {c.fragment});
  }
}

}  // namespace hair_material_test
}  // namespace rtpro
