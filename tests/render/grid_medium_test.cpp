// The grid medium kind's render side: along a slab of a density ramp, ratio tracking's estimate and
// the fraction delta tracking lets through both equal exp(−∫σt) per channel; the majorant segments
// bound σt wherever tracking can land; emission from a temperature grid is Cycles' blackbody.
#include "blackbody.h"
#include "grid_medium.h"
#include "medium_tracking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

namespace rtpro {
namespace grid_medium_test {

constexpr float kVoxel = 0.125f;  // scene units per voxel

// 16 × 4 × 4 voxels whose density rises linearly with x, value(x) = x / 15 for x in 0..15 (and
// `temperature` kelvin × the same ramp when asked), placed at `kVoxel` units per voxel. Trilinear
// lookups reproduce a ramp exactly, so along y = z = 1.5 the density is x / 15 on [0, 15] and falls
// from 1 to 0 over the last voxel: ∫ = 7.5 + 0.5 = 8 voxels = 1 scene unit.
GridMedium ramp(const Color& sigma_a, const Color& sigma_s, bool temperature = false) {
  const auto make_grid = [] {
    VoxelGrid grid(VoxelBox{{0, 0, 0}, {15, 3, 3}}, 0.0f);
    for (std::int32_t x = 0; x <= 15; ++x)
      for (std::int32_t y = 0; y <= 3; ++y)
        for (std::int32_t z = 0; z <= 3; ++z)
          grid.brick_at({x, y, z})[static_cast<std::size_t>(((x & 7) << 6) | ((y & 7) << 3) | (z & 7))] =
              static_cast<float>(x) / 15.0f;
    grid.seal();
    grid.index_to_medium = Affine::scale(Vec3(kVoxel));
    grid.active_voxels = 16 * 4 * 4;
    return grid;
  };
  VdbGrids grids;
  grids.density = make_grid();
  if (temperature) grids.temperature = make_grid();
  GridMedium medium;
  medium.grid = std::make_shared<const GridVolume>(place_grid_volume(std::move(grids), Affine::identity(), {}));
  medium.sigma_a = sigma_a;
  medium.sigma_s = sigma_s;
  medium.temperature_scale = 3000.0f;
  return medium;
}

// Along +x through the grid's middle, from well before it to well past it.
Ray through_ramp() {
  return Ray{{-1.0f, 1.5f * kVoxel, 1.5f * kVoxel}, 0.0f, {1.0f, 0.0f, 0.0f}, std::numeric_limits<float>::infinity()};
}
constexpr float kEnd = 4.0f;

constexpr int kWalks = 20000;

template <class F>
std::pair<double, double> mean_and_error(F estimate) {
  double sum = 0.0, squares = 0.0;
  for (int i = 0; i < kWalks; ++i) {
    const double x = estimate(i);
    sum += x;
    squares += x * x;
  }
  const double mean = sum / kWalks;
  return {mean, std::sqrt(std::max(0.0, squares / kWalks - mean * mean) / kWalks)};
}

TEST(GridMedium, SlabTransmittanceByRatioAndDeltaTrackingIsExpOfTheIntegral) {
  const Color sigma_a{0.2f, 0.6f, 1.5f}, sigma_s{0.6f, 0.5f, 0.3f};
  const Medium medium = ramp(sigma_a, sigma_s);
  for (int c = 0; c < 3; ++c) {
    const double expected = std::exp(-(sigma_a[c] + sigma_s[c]) * 1.0);  // ∫density = 1 scene unit
    SCOPED_TRACE("channel " + std::to_string(c));
    const auto [ratio, ratio_error] = mean_and_error([&](int i) {
      TrackingRandom random(mix64(i));
      return transmittance(medium, through_ramp(), kEnd, random)[c];
    });
    EXPECT_NEAR(ratio, expected, 5.0 * ratio_error + 1e-4);
    const auto [delta, delta_error] = mean_and_error([&](int i) {
      TrackingRandom random(mix64(i) ^ 0x5555);
      const TrackedRay tracked = delta_track(medium, through_ramp(), kEnd, random.next(), random, Color(1.0f));
      return tracked.event == TrackedRay::Event::kPassed ? tracked.beta[c] : 0.0f;
    });
    EXPECT_NEAR(delta, expected, 5.0 * delta_error + 1e-4);
    EXPECT_NEAR(delta, ratio, 5.0 * std::hypot(delta_error, ratio_error) + 1e-4);
  }
}

TEST(GridMedium, CoefficientsScaleTheTrilinearDensityAndTheMajorantsBoundThem) {
  const GridMedium medium = ramp({0.5f, 1.0f, 2.0f}, {1.5f, 1.0f, 0.0f});
  const MediumPoint point = medium_point(medium, {6.0f * kVoxel, 1.5f * kVoxel, 1.5f * kVoxel});
  EXPECT_NEAR(point.sigma_a.z, 2.0f * 6.0f / 15.0f, 1e-5f);
  EXPECT_NEAR(point.sigma_s.x, 1.5f * 6.0f / 15.0f, 1e-5f);
  EXPECT_EQ(point.emission, Color(0.0f));
  EXPECT_FALSE(only_absorbs(medium));
  EXPECT_TRUE(only_absorbs(ramp(Color(1.0f), Color(0.0f))));
  EXPECT_FALSE(closed_form_transmittance(medium, through_ramp(), kEnd));
  // Segments in order, inside the grid's box, each bounding σt at points along it.
  const Ray ray{{-1.0f, 0.2f, 0.3f}, 0.0f, normalize(Vec3{1.0f, 0.05f, -0.02f}), kEnd};
  auto segments = majorants(medium, ray, kEnd);
  float last = 0.0f;
  int count = 0;
  while (const std::optional<MajorantSegment> s = segments.next()) {
    ++count;
    EXPECT_GE(s->t_min, last);
    last = s->t_max;
    for (int k = 0; k <= 8; ++k) {
      const MediumPoint p = medium_point(medium, ray.at(s->t_min + (s->t_max - s->t_min) * float(k) / 8.0f));
      EXPECT_LE(max_component(p.sigma_a + p.sigma_s), s->sigma_maj * (1.0f + 1e-5f));
    }
  }
  EXPECT_GT(count, 0);
  // The last segment ends where the ray leaves the grid's box (x = 2: a voxel past the last centre).
  EXPECT_NEAR(last, (2.0f + 1.0f) / ray.dir.x, 1e-3f);
}

TEST(GridMedium, TemperatureGridsEmitCyclesBlackbody) {
  // Luminance 1, Cycles' colours at the ends of its range, and σT⁴·1e-6/π in total.
  for (const float kelvin : {800.0f, 1500.0f, 3000.0f, 6500.0f, 12000.0f}) {
    const Color c = blackbody_color(kelvin);
    EXPECT_NEAR(0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z, 1.0f, 2e-3f) << kelvin;
  }
  const Color hot = blackbody_color(12000.0f);
  EXPECT_NEAR(hot.x, 0.826f, 0.02f);
  EXPECT_NEAR(hot.y, 0.995f, 0.02f);
  EXPECT_NEAR(hot.z, 1.566f, 0.03f);
  const Color d65 = blackbody_color(6504.0f);  // near white
  EXPECT_NEAR(d65.x, 1.0f, 0.06f);
  EXPECT_NEAR(d65.z, 1.0f, 0.06f);
  EXPECT_EQ(blackbody_emission(0.0f), Color(0.0f));
  const Color e = blackbody_emission(2000.0f);
  const float luminance = 0.2126f * e.x + 0.7152f * e.y + 0.0722f * e.z;
  EXPECT_NEAR(luminance, 5.670374e-8f * 1e-6f / 3.14159265f * 1.6e13f, 3e-3f);
  // The temperature grid is read through its scale: 3000 K × 10/15 at x = 10.
  const GridMedium medium = ramp(Color(1.0f), Color(0.0f), true);
  EXPECT_FALSE(only_absorbs(medium));
  const MediumPoint point = medium_point(medium, {10.0f * kVoxel, 1.5f * kVoxel, 1.5f * kVoxel});
  const Color expected = blackbody_emission(2000.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(point.emission[c], expected[c], 1e-4f * expected[c] + 1e-9f);
}

}  // namespace grid_medium_test
}  // namespace rtpro
