// The environment light: its latitude-longitude mapping, its rotation, and its sampler against
// its pdf (χ², pbrt's test) on images with sharp features, as well as a constant environment.
#include "rtpro/render/environment_light.h"

#include "bsdf_test_support.h"
#include "rtpro/core/math_constants.h"

#include <gtest/gtest.h>

#include <cmath>
#include <future>
#include <vector>

namespace rtpro {
namespace environment_light_test {

using test::chi2_test;
using test::Chi2Outcome;
using test::kChi2Significance;
using test::Uniforms;
constexpr EnvironmentSampling kWhole = EnvironmentSampling::kWhole;
constexpr EnvironmentSampling kAboveMean = EnvironmentSampling::kAboveMean;

// An RGB image of `width` × `height` (top row first) of `background`, with pixel (x, y) `spot`.
Image image_with_spot(int width, int height, Color background, int x, int y, Color spot) {
  Image image(width, height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const Color c = (i == x && j == y) ? spot : background;
      image.at(i, j, 0) = c.x;
      image.at(i, j, 1) = c.y;
      image.at(i, j, 2) = c.z;
    }
  return image;
}

// A lumpy image: a gradient, a bright patch and black rows, like a sky over dark ground.
Image lumpy_image(int width, int height) {
  Image image(width, height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      float v = 0.2f + float(i) / width + 0.5f * float(j) / height;
      if (j >= height * 3 / 4) v = 0.0f;
      if (i >= width / 3 && i < width / 3 + 2 && j >= 2 && j < 4) v = 40.0f;
      image.at(i, j, 0) = v;
      image.at(i, j, 1) = 0.5f * v;
      image.at(i, j, 2) = (i % 3 == 0) ? 0.0f : v;
    }
  return image;
}

Environment environment(Affine to_world = Affine::identity(), Color scale = Color(1.0f)) {
  return Environment{"sky.exr", scale, to_world, true};
}

TEST(EnvironmentLight, ConstantEnvironmentIsTheSameEverywhereAndSampledUniformly) {
  const EnvironmentLight light(Environment{"", Color(0.5f, 1.0f, 2.0f), Affine::identity(), true}, Image(), kWhole);
  Uniforms uniforms(3);
  for (int i = 0; i < 100; ++i) {
    const Vec3 d = uniforms.next_direction();
    EXPECT_EQ(light.radiance(d), Color(0.5f, 1.0f, 2.0f));
    EXPECT_FLOAT_EQ(light.pdf(d), 1.0f / (4.0f * kPi));
    const std::optional<EnvironmentLight::Sample> s = light.sample(uniforms.next_2d());
    ASSERT_TRUE(s);
    EXPECT_NEAR(length(s->direction), 1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(s->pdf, 1.0f / (4.0f * kPi));
  }
  EXPECT_NEAR(light.mean_radiance(), 3.5f / 3.0f, 1e-6f);
}

TEST(EnvironmentLight, BlackEnvironmentIsNeverSampled) {
  const EnvironmentLight constant(Environment{"", Color(0.0f), Affine::identity(), true}, Image(), kWhole);
  EXPECT_FALSE(constant.sample({0.5f, 0.5f}));
  EXPECT_EQ(constant.pdf(Vec3(0, 1, 0)), 0.0f);
  const EnvironmentLight image(environment(), image_with_spot(8, 4, Color(0.0f), 0, 0, Color(0.0f)), kWhole);
  EXPECT_FALSE(image.sample({0.5f, 0.5f}));
}

// The documented frame: the top row is straight up, the centre column looks along +X, u = 0.25
// along −Z and u = 0.75 along +Z (Blender's world mapping, seen in glTF's +Y-up axes).
TEST(EnvironmentLight, ImageCentreLooksAlongPlusXAndTheTopRowUp) {
  constexpr int kWidth = 16, kHeight = 8;
  const auto radiance_towards = [&](int x, int y, const Vec3& direction) {
    const EnvironmentLight light(environment(), image_with_spot(kWidth, kHeight, Color(0.0f), x, y, Color(1.0f)),
                                 kWhole);
    return light.radiance(direction).x;
  };
  // The centre of pixel (x, y) is exactly one texel: full weight there.
  const auto centre_of = [&](int x, int y) {
    const float theta = kPi * (y + 0.5f) / kHeight, phi = 2.0f * kPi * ((x + 0.5f) / kWidth - 0.5f);
    return Vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  EXPECT_NEAR(radiance_towards(8, 3, centre_of(8, 3)), 1.0f, 1e-5f);
  // +X lies between columns 7 and 8 on the horizon (between rows 3 and 4): a quarter of each.
  EXPECT_NEAR(radiance_towards(8, 4, Vec3(1, 0, 0)), 0.25f, 1e-5f);
  EXPECT_NEAR(radiance_towards(7, 3, Vec3(1, 0, 0)), 0.25f, 1e-5f);
  EXPECT_NEAR(radiance_towards(3, 4, Vec3(0, 0, -1)), 0.25f, 1e-5f);  // u = 0.25: columns 3 and 4
  EXPECT_NEAR(radiance_towards(12, 4, Vec3(0, 0, 1)), 0.25f, 1e-5f);  // u = 0.75: columns 11 and 12
  EXPECT_NEAR(radiance_towards(0, 4, Vec3(-1, 0, 0)), 0.25f, 1e-5f);  // u = 0 and 1: wraps
  EXPECT_NEAR(radiance_towards(15, 4, Vec3(-1, 0, 0)), 0.25f, 1e-5f);
  // Straight up reads the top row only, straight down the bottom one.
  const auto row_lit = [&](int lit_row) {
    Image image(kWidth, kHeight);
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, lit_row, c) = 1.0f;
    return EnvironmentLight(environment(), image, kWhole);
  };
  EXPECT_NEAR(row_lit(0).radiance(Vec3(0, 1, 0)).x, 1.0f, 1e-6f);
  EXPECT_EQ(row_lit(0).radiance(Vec3(0, -1, 0)).x, 0.0f);
  EXPECT_NEAR(row_lit(kHeight - 1).radiance(Vec3(0, -1, 0)).x, 1.0f, 1e-6f);
  EXPECT_EQ(row_lit(kHeight - 1).radiance(Vec3(0, 1, 0)).x, 0.0f);
}

TEST(EnvironmentLight, RotationTurnsTheImageWithTheWorld) {
  const Affine turn = compose(Affine::rotate({0, 1, 0}, 70.0f), Affine::rotate({1, 0, 0}, -25.0f));
  const EnvironmentLight still(environment(), lumpy_image(32, 16), kWhole);
  const EnvironmentLight turned(environment(turn), lumpy_image(32, 16), kWhole);
  Uniforms uniforms(5);
  for (int i = 0; i < 200; ++i) {
    const Vec3 d = uniforms.next_direction();
    const Color a = still.radiance(d), b = turned.radiance(turn.apply_vector(d));
    EXPECT_NEAR(a.x, b.x, 1e-3f * (1.0f + a.x));
    EXPECT_NEAR(a.z, b.z, 1e-3f * (1.0f + a.z));
    EXPECT_NEAR(still.pdf(d), turned.pdf(turn.apply_vector(d)), 1e-3f * (1.0f + still.pdf(d)));
  }
}

TEST(EnvironmentLight, ScaleMultipliesTheImageAndNonFiniteOrNegativeTexelsAreBlack) {
  Image image = image_with_spot(8, 4, Color(1.0f), 2, 1, Color(-3.0f));
  image.at(5, 2, 1) = std::nanf("");
  image.at(6, 2, 2) = std::numeric_limits<float>::infinity();
  const EnvironmentLight light(environment(Affine::identity(), Color(2.0f, 3.0f, 4.0f)), image, kWhole);
  Uniforms uniforms(11);
  for (int i = 0; i < 2000; ++i) {
    const Color c = light.radiance(uniforms.next_direction());
    ASSERT_TRUE(is_finite(c));
    EXPECT_GE(c.x, 0.0f);
    EXPECT_LE(c.x, 2.0f + 1e-5f);
    EXPECT_LE(c.y, 3.0f + 1e-5f);
    EXPECT_LE(c.z, 4.0f + 1e-5f);
  }
}

// Wherever the filtered image shows light, the sampler can go: light sampling alone is unbiased.
TEST(EnvironmentLight, EveryDirectionThatShowsLightHasAPdf) {
  const EnvironmentLight light(environment(), image_with_spot(64, 32, Color(0.0f), 40, 9, Color(5.0f)), kWhole);
  Uniforms uniforms(17);
  int lit = 0;
  for (int i = 0; i < 400000; ++i) {
    const Vec3 d = uniforms.next_direction();
    if (max_component(light.radiance(d)) > 0.0f) {
      ++lit;
      EXPECT_GT(light.pdf(d), 0.0f);
    }
  }
  EXPECT_GT(lit, 50);
}

// Both strategies of multiple importance sampling must see one number for a direction, and the
// escaped ray's lookup by image coordinates must be the direction's own.
TEST(EnvironmentLight, ASampleCarriesExactlyItsDirectionsRadianceAndPdf) {
  const Affine turn = compose(Affine::rotate({0, 1, 0}, 70.0f), Affine::rotate({1, 0, 0}, -25.0f));
  const EnvironmentLight light(environment(turn), lumpy_image(32, 16), kWhole);
  Uniforms uniforms(11);
  int sampled = 0;
  for (int i = 0; i < 2000; ++i) {
    const std::optional<EnvironmentLight::Sample> s = light.sample(uniforms.next_2d());
    if (!s) continue;
    ++sampled;
    const Color radiance = light.radiance(s->direction);
    EXPECT_EQ(s->radiance.x, radiance.x);
    EXPECT_EQ(s->radiance.z, radiance.z);
    EXPECT_EQ(s->pdf, light.pdf(s->direction));
    const EnvironmentLight::ImageCoordinates uv = light.image_coordinates(s->direction);
    EXPECT_EQ(light.radiance_at(uv).y, radiance.y);
    EXPECT_EQ(light.pdf_at(uv), s->pdf);
  }
  EXPECT_GT(sampled, 1900);
}

// A direction without its pdf and radiance (the path integrator's, whose shadow ray may still be
// stopped) is sample()'s direction, and pdf() and radiance() of it are sample()'s, bit for bit;
// for a constant environment too, and there is none where sample() has none.
TEST(EnvironmentLight, ADirectionSampleIsTheSampleWithItsPdfAndRadianceLeftForLater) {
  const Affine turn = compose(Affine::rotate({0, 1, 0}, 35.0f), Affine::rotate({0, 0, 1}, 10.0f));
  for (const EnvironmentSampling sampling : {kWhole, kAboveMean}) {
    const EnvironmentLight light(environment(turn), lumpy_image(64, 32), sampling);
    const EnvironmentLight constant(Environment{"", Color(0.5f, 1.0f, 2.0f), Affine::identity(), true}, Image(),
                                    sampling);
    Uniforms uniforms(17);
    int sampled = 0;
    for (int i = 0; i < 4000; ++i) {
      const Sample2D u = uniforms.next_2d();
      for (const EnvironmentLight* l : {&light, &constant}) {
        const std::optional<EnvironmentLight::Sample> s = l->sample(u);
        const std::optional<Vec3> d = l->sample_direction(u);
        if (!d) {
          EXPECT_FALSE(s);
          continue;
        }
        if (!s) {  // a direction whose pdf, found again, is 0: sample() has none
          EXPECT_FALSE(l->pdf(*d) > 0.0f);
          continue;
        }
        ++sampled;
        EXPECT_EQ(*d, s->direction);
        EXPECT_EQ(l->pdf(*d), s->pdf);
        EXPECT_EQ(l->radiance(*d), s->radiance);
      }
    }
    EXPECT_GT(sampled, 7000);
  }
  const EnvironmentLight black(environment(), image_with_spot(8, 4, Color(0.0f), 0, 0, Color(0.0f)), kWhole);
  EXPECT_FALSE(black.sample_direction({0.5f, 0.5f}));
}

// Sampling above the mean: the left half of the image at 1, the right half at 3, so the mean over
// the sphere is 2. The dim half has no light samples and pdf 0 (BSDF samples cover it under MIS);
// the bright half takes them all, in proportion to its excess: 1 in each of its 14 inner columns
// and 0.75 in the 2 beside the dim half, where the bilinear filter mixes in an eighth of it, so
// 32/15.5 per unit of u there, over 4π per unit area of the image on the horizon.
TEST(EnvironmentLight, AboveTheMeanOnlyBrighterPixelsAreSampled) {
  constexpr int kWidth = 32, kHeight = 16;
  Image image(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c) image.at(x, y, c) = x < kWidth / 2 ? 1.0f : 3.0f;
  const EnvironmentLight light(environment(), image, kAboveMean);
  const EnvironmentLight whole(environment(), image, kWhole);
  EXPECT_EQ(light.sampling(), kAboveMean);
  // u = 0.25 (left half) looks along −Z, u = 0.75 (right half) along +Z, both on the horizon;
  // away from the halves' borders the bilinear lookup reads one value.
  EXPECT_EQ(light.pdf(Vec3(0, 0, -1)), 0.0f);
  EXPECT_GT(whole.pdf(Vec3(0, 0, -1)), 0.0f);
  // Within 1% of that: a row weighs the sin θ of its centre (0.995 beside the horizon).
  const float inner = 32.0f / 15.5f / (4.0f * kPi);
  EXPECT_NEAR(light.pdf(Vec3(0, 0, 1)), inner, 0.01f * inner);
  EXPECT_NEAR(light.pdf(Vec3(0.3f, 0, 1)), inner, 0.01f * inner);
  EXPECT_EQ(light.pdf(Vec3(0.3f, 0, -1)), 0.0f);
  Uniforms uniforms(3);
  int right = 0, total = 0;
  for (int i = 0; i < 4000; ++i)
    if (const std::optional<EnvironmentLight::Sample> s = light.sample(uniforms.next_2d())) {
      ++total;
      right += light.image_coordinates(s->direction).u >= 0.5f - 1.0f / kWidth;
      EXPECT_GT(s->pdf, 0.0f);
    }
  EXPECT_EQ(total, 4000);
  EXPECT_EQ(right, total);
}

TEST(EnvironmentLight, AnImageOfOneColourIsSampledWholeEvenAboveTheMean) {
  const EnvironmentLight light(environment(), image_with_spot(16, 8, Color(0.7f), 0, 0, Color(0.7f)), kAboveMean);
  EXPECT_EQ(light.sampling(), kWhole);
  EXPECT_GT(light.pdf(Vec3(0, 0, 1)), 0.0f);
  EXPECT_GT(light.pdf(Vec3(0, 0, -1)), 0.0f);
}

TEST(EnvironmentLight, GreyImagesAreReadAsEqualChannels) {
  Image grey(4, 2, {"Y"});
  for (float& v : grey.data) v = 0.75f;
  const EnvironmentLight light(environment(), grey, kWhole);
  EXPECT_EQ(light.radiance(Vec3(0.3f, 0.2f, -0.5f)), Color(0.75f));
}

void expect_sampler_matches_pdf(const EnvironmentLight& light, const char* label) {
  const Chi2Outcome outcome = chi2_test(
      [&](float, Sample2D u) -> std::optional<Vec3> {
        const std::optional<EnvironmentLight::Sample> s = light.sample(u);
        if (!s) return std::nullopt;
        EXPECT_NEAR(s->pdf, light.pdf(s->direction), 1e-4f * s->pdf) << label;
        return s->direction;
      },
      [&](const Vec3& w) { return light.pdf(w); }, 400'000, 29);
  ASSERT_TRUE(outcome.failure.empty()) << label << ": " << outcome.failure;
  EXPECT_NEAR(outcome.pdf_integral, 1.0, 2e-3) << label;
  EXPECT_GT(outcome.sampled_fraction, 0.999) << label;
  EXPECT_GT(outcome.p_value, kChi2Significance)
      << label << ": χ² " << outcome.chi2 << " with " << outcome.dof << " dof";
}

// Each case on its own thread: the pdf's integral over the bins dominates, and is adaptive.
TEST(EnvironmentLightChi2, SamplerMatchesPdf) {
  std::vector<std::future<void>> cases;
  cases.push_back(std::async(std::launch::async, [] {
    expect_sampler_matches_pdf(
        EnvironmentLight(environment(Affine::rotate({1, 1, 0}, 40.0f)), lumpy_image(48, 24), kWhole), "lumpy, rotated");
  }));
  cases.push_back(std::async(std::launch::async, [] {
    expect_sampler_matches_pdf(
        EnvironmentLight(environment(), image_with_spot(32, 16, Color(0.1f), 20, 5, Color(300.0f)), kWhole), "sun");
  }));
  cases.push_back(std::async(std::launch::async, [] {
    expect_sampler_matches_pdf(
        EnvironmentLight(environment(Affine::rotate({1, 1, 0}, 40.0f)), lumpy_image(48, 24), kAboveMean),
        "lumpy, rotated, above the mean");
  }));
  cases.push_back(std::async(std::launch::async, [] {
    expect_sampler_matches_pdf(
        EnvironmentLight(environment(), image_with_spot(32, 16, Color(0.1f), 20, 5, Color(300.0f)), kAboveMean),
        "sun, above the mean");
  }));
  cases.push_back(std::async(std::launch::async, [] {
    expect_sampler_matches_pdf(
        EnvironmentLight(Environment{"", Color(1.0f), Affine::identity(), true}, Image(), kWhole), "constant");
  }));
  for (auto& c : cases) c.get();
}

}  // namespace environment_light_test
}  // namespace rtpro
