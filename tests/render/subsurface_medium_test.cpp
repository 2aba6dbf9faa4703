// The medium under a subsurface material (render/media/subsurface_medium.h): the albedo inversion
// does what it is for — a random walk of the single-scattering albedo it gives, in a half-space
// entered through a Lambert lobe, reflects the surface albedo asked for — and the radius becomes
// the mean free path as each of Cycles' two methods says.
#include "subsurface_medium.h"

#include "hg_phase.h"
#include "rtpro/core/math_constants.h"
#include "rtpro/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace rtpro {
namespace {

// Walks into the half-space z < 0 of medium `m` (channel 0), entering along cosine-distributed
// directions; the fraction of their weight that comes back out through z = 0, where each leaves.
double half_space_reflectance(const SubsurfaceMedium& m, int walks) {
  std::uint64_t state = 12345;
  const auto next = [&] { return to_unit_float(mix64(state++)); };
  double reflected = 0.0;
  for (int w = 0; w < walks; ++w) {
    const float r = std::sqrt(next()), phi = 2.0f * kPi * next();
    Vec3 position{0.0f, 0.0f, 0.0f};
    Vec3 direction{r * std::cos(phi), r * std::sin(phi), -std::sqrt(std::max(0.0f, 1.0f - r * r))};
    double weight = m.weight.x;
    for (int step = 0; step < 256; ++step) {
      if (step > 0) {
        weight *= m.albedo.x;
        direction = sample_henyey_greenstein(direction, m.anisotropy, {next(), next()}).outgoing;
      }
      const float t = -std::log1p(-next()) / m.sigma_t.x;
      position = position + direction * t;
      if (position.z > 0.0f) {
        reflected += weight;
        break;
      }
    }
  }
  return reflected / walks;
}

TEST(SubsurfaceMedium, HalfSpaceWalkReflectsTheSurfaceAlbedo) {
  for (const float g : {0.0f, 0.7f})
    for (const float albedo : {0.15f, 0.8f}) {
      const SubsurfaceMedium m =
          subsurface_medium(Color(albedo), Color(1.0f), g, 1.4f, SubsurfaceMethod::kRandomWalkFixedRadius);
      SCOPED_TRACE("g = " + std::to_string(g) + ", albedo = " + std::to_string(albedo));
      // 10,000 walks: a standard error below 0.005; the fit itself is good to about 1%.
      const double reflectance = half_space_reflectance(m, 10000);
      std::cout << "[half-space] g " << g << ", albedo " << albedo << ": reflects " << reflectance << "\n";
      EXPECT_NEAR(reflectance, albedo, 0.025);
    }
}

TEST(SubsurfaceMedium, AlbedoInversionIsMonotoneAndBounded) {
  float previous = 0.0f;
  for (int i = 1; i <= 100; ++i) {
    const float alpha = single_scattering_albedo(i / 100.0f, 0.0f);
    EXPECT_GE(alpha, previous);
    previous = alpha;
  }
  EXPECT_EQ(single_scattering_albedo(1.0f, 0.0f), 0.999999f);  // a walk of albedo 1 would never end
  EXPECT_EQ(single_scattering_albedo(0.0f, 0.3f), 0.0f);
  // Dark albedos keep α at least 0.2 and lower the walk's weight instead.
  const SubsurfaceMedium dark =
      subsurface_medium(Color(0.01f), Color(1.0f), 0.0f, 1.4f, SubsurfaceMethod::kRandomWalkFixedRadius);
  EXPECT_FLOAT_EQ(dark.albedo.x, 0.2f);
  EXPECT_NEAR(dark.weight.x, single_scattering_albedo(0.01f, 0.0f) / 0.2f, 1e-6f);
}

TEST(SubsurfaceMedium, DipoleInverseRoundTrips) {
  for (const float boundary : {2.0f, 3.5f, 6.0f})
    for (const float reduced : {0.3f, 0.8f, 0.95f, 0.999f}) {
      // Twelve halvings of [0, 1]: α' to within 2⁻¹².
      EXPECT_NEAR(dipole_reduced_albedo(dipole_reflectance(reduced, boundary), boundary), reduced, 0x1p-12f);
    }
}

TEST(SubsurfaceMedium, RadiusBecomesTheMeanFreePath) {
  const Color radius{1.0f, 0.5f, 0.25f};
  // Fixed radius: ℓ = r/(4π), σt = 1/(ℓ (1 − g)).
  const SubsurfaceMedium fixed =
      subsurface_medium(Color(0.5f), radius, 0.5f, 1.4f, SubsurfaceMethod::kRandomWalkFixedRadius);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fixed.sigma_t[c] * radius[c], 4.0f * kPi / 0.5f, 1e-3f);
  // Random walk: r is the diffusion length, ℓ = r·√(3(1 − α')), α' shorter paths for brighter albedo.
  const SubsurfaceMedium bright = subsurface_medium(Color(0.9f), radius, 0.0f, 1.4f, SubsurfaceMethod::kRandomWalk);
  const SubsurfaceMedium dull = subsurface_medium(Color(0.3f), radius, 0.0f, 1.4f, SubsurfaceMethod::kRandomWalk);
  for (int c = 0; c < 3; ++c) EXPECT_GT(bright.sigma_t[c], dull.sigma_t[c]);
  const float inv_eta = 1.0f / 1.4f;
  const float fdr = inv_eta * (-1.44f * inv_eta + 0.71f) + 0.668f + 0.0636f * 1.4f;
  const float boundary = (4.0f / 3.0f) * (1.0f + fdr) / (1.0f - fdr);
  const float path = std::sqrt(3.0f * (1.0f - dipole_reduced_albedo(0.3f, boundary)));
  EXPECT_NEAR(dull.sigma_t.x, 1.0f / path, 1e-4f);
}

TEST(SubsurfaceMedium, CacheGivesTheMediumOfItsLatestInputs) {
  // Each input alone changed must make the medium again; the same inputs again, the same medium.
  struct Inputs {
    Color albedo, radius;
    float anisotropy, ior;
    SubsurfaceMethod method;
  };
  const Inputs base{Color(0.8f, 0.5f, 0.3f), Color(1.0f, 0.5f, 0.25f), 0.3f, 1.4f, SubsurfaceMethod::kRandomWalk};
  std::vector<Inputs> sequence{base, base};
  for (int change = 0; change < 5; ++change) {
    Inputs other = base;
    if (change == 0) other.albedo = Color(0.8f, 0.5f, 0.4f);
    if (change == 1) other.radius = Color(1.0f, 0.6f, 0.25f);
    if (change == 2) other.anisotropy = 0.5f;
    if (change == 3) other.ior = 1.3f;
    if (change == 4) other.method = SubsurfaceMethod::kRandomWalkFixedRadius;
    sequence.push_back(other);
    sequence.push_back(base);
  }
  SubsurfaceMediumCache cache;
  for (const Inputs& in : sequence) {
    const SubsurfaceMedium& got = cache.get(in.albedo, in.radius, in.anisotropy, in.ior, in.method);
    const SubsurfaceMedium want = subsurface_medium(in.albedo, in.radius, in.anisotropy, in.ior, in.method);
    EXPECT_EQ(got.sigma_t, want.sigma_t);
    EXPECT_EQ(got.albedo, want.albedo);
    EXPECT_EQ(got.anisotropy, want.anisotropy);
    EXPECT_EQ(got.weight, want.weight);
  }
}

}  // namespace
}  // namespace rtpro
