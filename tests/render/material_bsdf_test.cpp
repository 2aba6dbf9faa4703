// reads_lobe_choice may say "no" only for materials whose BSDF sample does not depend on u_lobe:
// the path integrator then leaves that random number undrawn, and a wrong "no" would feed such a
// BSDF a stale number.
#include "material_bsdf.h"

#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <string>

namespace rtpro {
namespace material_bsdf_test {

RenderScene material_scene() {
  return build_render_scene(parse_scene_text(R"(
rtpro: 1
camera: {position: [0, 1, -5], look_at: [0, 1, 0]}
materials:
  phong: {color: [0.8, 0.2, 0.1], specular: 0.5, shininess: 40}
  phong_matte: {color: [0.8, 0.2, 0.1], specular: 0}
  phong_mirror: {color: [0.1, 0.1, 0.1], specular: 0, reflectivity: 0.8}
  phong_glass: {ior: 1.5, specular: 0.9, shininess: 400}
  diffuse: {type: diffuse, color: [0.3, 0.6, 0.2]}
  gold: {type: conductor, eta: [0.143, 0.374, 1.442], k: [3.983, 2.385, 1.603], roughness: 0.25}
  glass: {type: dielectric, ior: 1.5}
  rough_glass: {type: dielectric, ior: 1.5, roughness: 0.3}
  coated: {type: principled, color: [0.6, 0.04, 0.04], roughness: 0.5, coat_weight: 1, coat_roughness: 0.05}
lights:
  - {type: point, position: [0, 3, 0], intensity: 5}
world:
  - {type: sphere, center: [0, 0, 0], radius: 1, material: phong}
)",
                                             "materials.yaml"));
}

bool same(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

bool same_sample(const std::optional<BsdfSample>& a, const std::optional<BsdfSample>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  return same(a->wi.x, b->wi.x) && same(a->wi.y, b->wi.y) && same(a->wi.z, b->wi.z) && same(a->pdf, b->pdf) &&
         same(a->f.x, b->f.x) && same(a->f.y, b->f.y) && same(a->f.z, b->f.z) && a->delta == b->delta &&
         a->transmitted == b->transmitted;
}

// Whether any of many samples changes with u_lobe alone.
bool sample_depends_on_lobe_choice(const Material& material) {
  SurfacePoint point{};
  point.geometric_normal = point.shading_normal = {0.0f, 0.0f, 1.0f};
  point.front_face = true;
  const SurfaceBsdf surface = material_bsdf(material, point, nullptr);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    const float z = unit(rng) * 2.0f - 1.0f;
    const Vec3 wo = normalize(Vec3{unit(rng) - 0.5f, unit(rng) - 0.5f, z == 0.0f ? 0.5f : z});
    const Sample2D u{unit(rng), unit(rng)};
    const std::optional<BsdfSample> first = bsdf_sample(surface.bsdf, wo, unit(rng), u);
    if (!same_sample(first, bsdf_sample(surface.bsdf, wo, unit(rng), u))) return true;
  }
  return false;
}

TEST(MaterialBsdf, OnlyMaterialsWhoseSampleIgnoresTheLobeChoiceSayTheyDoNotReadIt) {
  const RenderScene scene = material_scene();
  ASSERT_EQ(scene.materials.size(), scene.material_names.size());
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const std::string& name = scene.material_names[m];
    const bool reads = reads_lobe_choice(scene.materials[m]);
    // Lambert surfaces (a Phong material's without highlight or mirror too, in the path
    // integrator; the default material has a highlight) have one lobe.
    EXPECT_EQ(reads, name != "phong_matte" && name != "diffuse") << name;
    // And every kind that says it reads the choice does, with these parameters: the test tells
    // them apart.
    EXPECT_EQ(sample_depends_on_lobe_choice(scene.materials[m]), reads) << name;
  }
}

TEST(MaterialBsdf, SaysWhichMaterialsMakeLambertSurfaces) {
  const RenderScene scene = material_scene();
  SurfacePoint point{};
  point.geometric_normal = point.shading_normal = {0.0f, 0.0f, 1.0f};
  point.front_face = true;
  for (std::size_t m = 0; m < scene.materials.size(); ++m) {
    const SurfaceBsdf surface = material_bsdf(scene.materials[m], point, nullptr);
    EXPECT_EQ(makes_lambert_bsdf(scene.materials[m]), std::holds_alternative<DiffuseBsdf>(surface.bsdf))
        << scene.material_names[m];
  }
}

}  // namespace material_bsdf_test
}  // namespace rtpro
