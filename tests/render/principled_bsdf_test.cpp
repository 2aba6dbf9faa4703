// The glTF metallic-roughness material: its sampler matches its pdf (χ²) for each kind of layer
// stack; sampled f and pdf are eval's and pdf's; it never creates energy, and albedo scaling keeps
// a white dielectric, a white metal and a coat or fuzz over white near 1 at every roughness, and
// energy compensation white rough glass at 1 from either side; its
// limits are the simpler kinds (metalness 1 is ConductorBsdf, specular weight 0 is Lambert
// exactly); the opaque model is reciprocal; smooth surfaces become delta lobes.
#include "principled_bsdf.h"

#include "bsdf.h"
#include "conductor_bsdf.h"
#include "diffuse_bsdf.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace rtpro {
namespace principled_bsdf_test {

// Fewer than the other kinds' χ² runs: eight stacks, and every sample evaluates all the lobes.
constexpr int kChi2Samples = 200'000;
const Color kCopper{0.955f, 0.638f, 0.538f};

PrincipledParameters white_dielectric(float roughness) {
  PrincipledParameters p;
  p.base_color = Color(1.0f);
  p.roughness = roughness;
  return p;
}

PrincipledParameters metal(const Color& color, float roughness) {
  PrincipledParameters p;
  p.base_color = color;
  p.metalness = 1.0f;
  p.roughness = roughness;
  return p;
}

PrincipledParameters coated(const PrincipledParameters& below, float coat_roughness) {
  PrincipledParameters p = below;
  p.coat_weight = 1.0f;
  p.coat_roughness = coat_roughness;
  return p;
}

PrincipledParameters fuzzy(const PrincipledParameters& below, const Color& fuzz, float fuzz_roughness) {
  PrincipledParameters p = below;
  p.fuzz_color = fuzz;
  p.fuzz_roughness = fuzz_roughness;
  return p;
}

PrincipledParameters glass(float roughness, const Color& tint = Color(1.0f)) {
  PrincipledParameters p;
  p.base_color = tint;
  p.roughness = roughness;
  p.transmission_weight = 1.0f;
  return p;
}

std::vector<Vec3> directions(const std::vector<float>& cosines) {
  std::vector<Vec3> wos;
  for (float c : cosines) wos.push_back(test::direction(c, 1.3f * c + 0.2f));
  return wos;
}

const std::vector<float> kOpaqueCosines{0.85f, 0.25f, -0.6f};

struct Chi2Case {
  std::string label;
  PrincipledParameters parameters;
  std::vector<float> cosines;
};

std::vector<Chi2Case> chi2_cases() {
  PrincipledParameters mixed = metal({0.9f, 0.6f, 0.3f}, 0.5f);
  mixed.metalness = 0.5f;
  PrincipledParameters rough_base;
  rough_base.base_color = {0.2f, 0.5f, 0.8f};
  rough_base.roughness = 0.6f;
  PrincipledParameters lambert;
  lambert.base_color = Color(0.5f);
  lambert.specular_weight = 0.0f;
  return {
      {"white dielectric roughness 0.3", white_dielectric(0.3f), kOpaqueCosines},
      {"white dielectric roughness 0.7", white_dielectric(0.7f), kOpaqueCosines},
      {"copper roughness 0.4", metal(kCopper, 0.4f), kOpaqueCosines},
      {"metalness 0.5 roughness 0.5", mixed, kOpaqueCosines},
      {"coat 0.25 over roughness 0.6", coated(rough_base, 0.25f), kOpaqueCosines},
      {"fuzz 0.4 over Lambert", fuzzy(lambert, {0.9f, 0.7f, 0.5f}, 0.4f), kOpaqueCosines},
      {"transmission roughness 0.5, outside", glass(0.5f, {1.0f, 0.9f, 0.8f}), {0.9f, 0.45f, 0.12f}},
      {"transmission roughness 0.5, inside", glass(0.5f, {1.0f, 0.9f, 0.8f}), {-0.9f, -0.6f, -0.25f}},
  };
}

void PrintTo(const Chi2Case& c, std::ostream* out) { *out << c.label; }

class PrincipledChi2 : public testing::TestWithParam<Chi2Case> {};

TEST_P(PrincipledChi2, SamplerMatchesPdf) {
  const PrincipledBsdf bsdf(GetParam().parameters);
  ASSERT_FALSE(bsdf.is_delta());
  test::expect_sampler_matches_pdf(GetParam().label, bsdf, directions(GetParam().cosines), kChi2Samples);
}

INSTANTIATE_TEST_SUITE_P(Stacks, PrincipledChi2, testing::ValuesIn(chi2_cases()),
                         [](const testing::TestParamInfo<Chi2Case>& info) {
                           return "Stack" + std::to_string(info.index);
                         });

// Many parameter sets, rough and smooth, over every combination of layers.
std::vector<PrincipledParameters> every_parameter_set() {
  std::vector<PrincipledParameters> sets;
  test::Uniforms uniforms(97);
  for (float roughness : {0.0f, 0.15f, 0.5f, 1.0f})
    for (float metalness : {0.0f, 0.4f, 1.0f})
      for (int layers = 0; layers < 8; ++layers) {
        PrincipledParameters p;
        p.base_color = {uniforms.next(), uniforms.next(), uniforms.next()};
        p.roughness = roughness;
        p.metalness = metalness;
        p.ior = 1.0f + uniforms.next();
        p.specular_weight = uniforms.next();
        p.specular_color = {1.0f, 0.5f + uniforms.next(), 1.0f};
        if (layers & 1) p.transmission_weight = 0.3f + 0.7f * uniforms.next();
        if (layers & 2) {
          p.coat_weight = 0.5f + 0.5f * uniforms.next();
          p.coat_roughness = layers & 4 ? 0.0f : uniforms.next();
        }
        if (layers & 4) {
          p.fuzz_color = {uniforms.next(), uniforms.next(), 1.0f};
          p.fuzz_roughness = uniforms.next();
        }
        sets.push_back(p);
      }
  return sets;
}

std::string describe(const PrincipledParameters& p) {
  std::ostringstream out;
  out << std::setprecision(3) << "base (" << p.base_color.x << ", " << p.base_color.y << ", " << p.base_color.z
      << ") metalness " << p.metalness << " roughness " << p.roughness << " ior " << p.ior << " specular "
      << p.specular_weight << " transmission " << p.transmission_weight << " coat " << p.coat_weight << "/"
      << p.coat_roughness << " fuzz " << max_component(p.fuzz_color) << "/" << p.fuzz_roughness;
  return out.str();
}

TEST(PrincipledBsdf, SampleAgreesWithEvalAndPdf) {
  test::Uniforms uniforms(11);
  int checked = 0;
  for (const PrincipledParameters& p : every_parameter_set()) {
    const PrincipledBsdf bsdf(p);
    for (int i = 0; i < 100; ++i) {
      const Vec3 wo = uniforms.next_direction();
      const auto s = uniforms.sample(bsdf, wo);
      if (!s || s->delta) continue;
      ASSERT_EQ(s->transmitted, !same_hemisphere(wo, s->wi)) << describe(p);
      const Color f = bsdf.eval(wo, s->wi);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(s->f[k], f[k], 1e-5f * f[k]) << describe(p);
      EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-5f * s->pdf) << describe(p);
      EXPECT_GT(s->pdf, 0.0f);
      ++checked;
    }
  }
  EXPECT_GT(checked, 5000);
}

// Light crossing into glass is diluted by 1/η² and concentrated by η² leaving it, without energy
// being created or lost: the energy albedo takes that factor back out of transmitted samples.
struct EnergyView {
  const PrincipledBsdf& bsdf;
  float eta;
  std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const {
    auto s = bsdf.sample(wo, u_lobe, u);
    if (s && s->transmitted) {
      const float etap = wo.z > 0.0f ? eta : 1.0f / eta;
      s->f = s->f * (etap * etap);
    }
    return s;
  }
};

Color energy_albedo(const PrincipledParameters& p, float cos_theta, int count = 16384) {
  const PrincipledBsdf bsdf(p);
  return test::estimate_albedo(EnergyView{bsdf, std::max(1.0f, p.ior)}, test::direction(cos_theta, 0.7f), count);
}

TEST(PrincipledBsdf, NeverCreatesEnergy) {
  for (const PrincipledParameters& p : every_parameter_set()) {
    const bool transmits = p.transmission_weight > 0.0f;
    for (float c : {1.0f, 0.6f, 0.25f, 0.08f, -0.4f, -0.9f}) {
      if (c < 0.0f && !transmits && c != -0.4f) continue;  // opaque: one look from behind suffices
      const Color albedo = energy_albedo(p, c, 4096);
      EXPECT_LE(max_component(albedo), 1.01f) << describe(p) << ", cos " << c;
    }
  }
}

void print_energy(const std::string& label, float parameter, float c, float energy) {
  std::ostringstream line;
  line << std::fixed << std::setprecision(4) << "[energy] " << label << " " << parameter << " cos=" << c
       << " albedo=" << energy << "\n";
  std::cout << line.str();
}

constexpr float kEnergyCosines[] = {1.0f, 0.7f, 0.4f, 0.15f, 0.05f};

TEST(PrincipledBsdf, AWhiteDielectricReflectsWhatItReceives) {
  for (float roughness : {0.0f, 0.3f, 0.7f, 1.0f})
    for (float c : kEnergyCosines) {
      const float energy = energy_albedo(white_dielectric(roughness), c, 65536).x;
      print_energy("white dielectric, roughness", roughness, c, energy);
      EXPECT_GE(energy, 0.97f) << "roughness " << roughness << ", cos " << c;
      EXPECT_LE(energy, 1.01f) << "roughness " << roughness << ", cos " << c;
    }
}

TEST(PrincipledBsdf, AWhiteMetalReflectsWhatItReceives) {
  for (float roughness : {0.0f, 0.3f, 0.7f, 1.0f})
    for (float c : kEnergyCosines) {
      const float energy = energy_albedo(metal(Color(1.0f), roughness), c, 65536).x;
      print_energy("white metal, roughness", roughness, c, energy);
      EXPECT_GE(energy, 0.98f) << "roughness " << roughness << ", cos " << c;
      EXPECT_LE(energy, 1.01f) << "roughness " << roughness << ", cos " << c;
    }
}

TEST(PrincipledBsdf, CoatAndFuzzOverWhiteKeepTheEnergy) {
  for (float roughness : {0.0f, 0.3f, 0.8f})
    for (float c : kEnergyCosines) {
      const PrincipledParameters base = white_dielectric(0.5f);
      const float coat = energy_albedo(coated(base, roughness), c, 65536).x;
      const float fuzz = energy_albedo(fuzzy(base, Color(1.0f), std::max(roughness, 0.1f)), c, 65536).x;
      const float both = energy_albedo(fuzzy(coated(base, roughness), Color(1.0f), 0.5f), c, 65536).x;
      print_energy("coat over white, coat roughness", roughness, c, coat);
      print_energy("fuzz over white, fuzz roughness", std::max(roughness, 0.1f), c, fuzz);
      print_energy("coat over fuzz over white, coat roughness", roughness, c, both);
      for (float energy : {coat, fuzz, both}) {
        EXPECT_GE(energy, 0.95f) << "roughness " << roughness << ", cos " << c;
        EXPECT_LE(energy, 1.01f) << "roughness " << roughness << ", cos " << c;
      }
    }
}

TEST(PrincipledBsdf, MetalnessOneIsTheConductor) {
  test::Uniforms uniforms(13);
  for (float roughness : {0.2f, 0.5f, 0.9f}) {
    const PrincipledBsdf principled(metal(kCopper, roughness));
    const ConductorBsdf conductor = ConductorBsdf::from_f0(kCopper, roughness_to_alpha(roughness));
    for (int i = 0; i < 300; ++i) {
      const Vec3 wo = uniforms.next_direction();
      const Vec3 wi = uniforms.next_direction();
      const Color a = principled.eval(wo, wi), b = conductor.eval(wo, wi);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-6f * b[k]);
      EXPECT_NEAR(principled.pdf(wo, wi), conductor.pdf(wo, wi), 1e-6f * conductor.pdf(wo, wi));
    }
  }
  const PrincipledBsdf mirror(metal(kCopper, 0.0f));
  EXPECT_TRUE(mirror.is_delta());
  const Vec3 wo = test::direction(0.6f, 1.0f);
  const auto s = mirror.sample(wo, 0.5f, {0.3f, 0.7f});
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->delta);
  const Color throughput = s->f * (std::fabs(s->wi.z) / s->pdf);
  const Color fresnel = ConductorBsdf::from_f0(kCopper, 0.0f).fresnel(0.6f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(throughput[k], fresnel[k], 1e-6f);
}

TEST(PrincipledBsdf, SpecularWeightZeroIsExactlyLambert) {
  PrincipledParameters p;
  p.base_color = {0.7f, 0.4f, 0.2f};
  p.specular_weight = 0.0f;
  for (float roughness : {0.0f, 0.5f}) {
    p.roughness = roughness;
    const PrincipledBsdf principled(p);
    const DiffuseBsdf lambert{p.base_color};
    EXPECT_FALSE(principled.is_delta());
    test::Uniforms uniforms(17);
    for (int i = 0; i < 300; ++i) {
      const Vec3 wo = uniforms.next_direction();
      const Vec3 wi = uniforms.next_direction();
      EXPECT_EQ(principled.eval(wo, wi), lambert.eval(wo, wi));
      EXPECT_EQ(principled.pdf(wo, wi), lambert.pdf(wo, wi));
      const float u_lobe = uniforms.next();
      const Sample2D u = uniforms.next_2d();
      const auto a = principled.sample(wo, u_lobe, u), b = lambert.sample(wo, u_lobe, u);
      ASSERT_EQ(a.has_value(), b.has_value());
      if (!a) continue;
      EXPECT_EQ(a->wi, b->wi);
      EXPECT_EQ(a->f, b->f);
      EXPECT_EQ(a->pdf, b->pdf);
    }
  }
}

TEST(PrincipledBsdf, OpaqueModelIsReciprocal) {
  test::Uniforms uniforms(19);
  int checked = 0;
  for (PrincipledParameters p : every_parameter_set()) {
    // Albedo scaling under the coat and the fuzz follows wo alone (OpenPBR's, Cycles'): only
    // the stack below them is reciprocal.
    p.transmission_weight = p.coat_weight = 0.0f;
    p.fuzz_color = Color(0.0f);
    const PrincipledBsdf bsdf(p);
    for (int i = 0; i < 50; ++i) {
      const Vec3 a = uniforms.next_direction(0.0f, 1.0f);
      const Vec3 b = uniforms.next_direction(0.0f, 1.0f);
      const Color ab = bsdf.eval(a, b), ba = bsdf.eval(b, a);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(ab[k], ba[k], 1e-4f * ab[k] + 1e-6f) << describe(p);
      checked += max_component(ab) > 0.0f;
    }
  }
  EXPECT_GT(checked, 2000);
}

TEST(PrincipledBsdf, DeltaOnlyWhenEveryLobeIsSmooth) {
  EXPECT_TRUE(PrincipledBsdf(metal(kCopper, 0.0f)).is_delta());
  EXPECT_TRUE(PrincipledBsdf(glass(0.0f)).is_delta());
  EXPECT_TRUE(PrincipledBsdf(coated(metal(kCopper, 0.0f), 0.0f)).is_delta());
  EXPECT_FALSE(PrincipledBsdf(coated(metal(kCopper, 0.0f), 0.3f)).is_delta());
  EXPECT_FALSE(PrincipledBsdf(white_dielectric(0.0f)).is_delta());  // the Lambert base
  EXPECT_FALSE(PrincipledBsdf(metal(kCopper, 0.3f)).is_delta());
  EXPECT_FALSE(PrincipledBsdf(fuzzy(metal(kCopper, 0.0f), Color(0.5f), 0.5f)).is_delta());
  EXPECT_FALSE(PrincipledBsdf(glass(0.2f)).is_delta());
}

// glTF's KHR_materials_transmission glass in the white furnace of the interface alone: the rough
// glass lobe's compensation (DielectricBsdf's table) keeps its energy from either side at every
// roughness, though its Fresnel term is Schlick's.
TEST(PrincipledBsdf, WhiteRoughGlassKeepsAllTheEnergyFromEitherSide) {
  for (float roughness : {0.1f, 0.3f, 0.5f, 0.7f, 1.0f})
    for (float c : {1.0f, 0.6f, 0.2f, -1.0f, -0.6f, -0.2f}) {
      const float energy = energy_albedo(glass(roughness), c, 16384).x;
      print_energy("white glass, roughness", roughness, c, energy);
      EXPECT_NEAR(energy, 1.0f, 0.01f) << "roughness " << roughness << ", cos " << c;
    }
}

TEST(PrincipledBsdf, SmoothGlassSplitsEnergyByFresnel) {
  const PrincipledBsdf bsdf(glass(0.0f));
  EXPECT_TRUE(bsdf.needs_outward_frame());
  EXPECT_FALSE(PrincipledBsdf(white_dielectric(0.3f)).needs_outward_frame());
  for (float c : {0.95f, 0.6f, 0.2f, -0.95f, -0.8f, -0.5f}) {
    const float energy = energy_albedo(glass(0.0f), c).x;
    EXPECT_NEAR(energy, 1.0f, 1e-4f) << "cos " << c;  // smooth: R + T = 1 exactly
  }
  // Beyond the critical angle from inside nothing leaves: every sample is a full reflection.
  const float critical_cos = std::sqrt(1.0f - 1.0f / (1.5f * 1.5f));
  const Vec3 wo = test::direction(-critical_cos * 0.95f, 0.3f);
  test::Uniforms uniforms(23);
  for (int i = 0; i < 100; ++i) {
    const auto s = uniforms.sample(bsdf, wo);
    ASSERT_TRUE(s.has_value());
    EXPECT_FALSE(s->transmitted);
    EXPECT_NEAR(s->f.x * std::fabs(s->wi.z) / s->pdf, 1.0f, 1e-5f);
  }
}

}  // namespace principled_bsdf_test
}  // namespace rtpro
