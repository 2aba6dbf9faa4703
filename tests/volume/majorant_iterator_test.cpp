#include "rtpro/volume/majorant_iterator.h"

#include "volume_test_grids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace rtpro {
namespace majorant_iterator_test {

std::vector<RayMajorantSegment> walk(DdaMajorantIterator it) {
  std::vector<RayMajorantSegment> segments;
  while (const auto segment = it.next()) segments.push_back(*segment);
  return segments;
}

struct TestRay {
  Vec3 origin, dir;
};

// Random rays at the grid from outside and inside, with axis-aligned ones, rays in a face's plane
// (grazing the box) and rays along the planes between cells.
std::vector<TestRay> test_rays(const MajorantGrid& grid, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
  const BBox& b = grid.bounds();
  auto inside = [&] {
    Vec3 p;
    for (int a = 0; a < 3; ++a) p[a] = b.lower[a] + (b.upper[a] - b.lower[a]) * uniform(random);
    return p;
  };
  auto direction = [&] {
    return normalize(Vec3(uniform(random) - 0.5f, uniform(random) - 0.5f, uniform(random) - 0.5f));
  };
  std::vector<TestRay> rays;
  for (int i = 0; i < 300; ++i) {
    const Vec3 target = inside(), dir = direction();
    rays.push_back({target - dir * 100.0f, dir});  // from outside
    rays.push_back({inside(), direction()});       // from inside
    Vec3 axis(0.0f);
    axis[i % 3] = i % 2 ? 1.0f : -1.0f;
    Vec3 start = inside();
    rays.push_back({start - axis * 100.0f, axis});  // axis-aligned
    Vec3 grazing = start;
    grazing[(i + 1) % 3] = i % 4 < 2 ? b.lower[(i + 1) % 3] : b.upper[(i + 1) % 3];
    Vec3 along = dir;
    along[(i + 1) % 3] = 0.0f;
    rays.push_back({grazing - along * 100.0f, along});  // in a face's plane
    Vec3 on_cell_plane = start;
    on_cell_plane[(i + 2) % 3] = grid.cell_bounds(1, 1, 1).lower[(i + 2) % 3];
    Vec3 in_plane = dir;
    in_plane[(i + 2) % 3] = 0.0f;
    rays.push_back({on_cell_plane, in_plane});  // between two layers of cells
  }
  return rays;
}

TEST(DdaMajorantIterator, SegmentsTileTheRaysOverlapWithTheGridInOrder) {
  const VoxelGrid grid = test::random_cloud(-5, 40, 0.02, 3);
  const MajorantGrid majorants(grid);
  const float sigma_t = 2.0f;
  int walked = 0;
  for (const TestRay& ray : test_rays(majorants, 5)) {
    float t0 = 0.0f, t1 = 1000.0f;
    const bool hits = clip_to_box(ray.origin, ray.dir, majorants.bounds(), t0, t1) && t0 < t1;
    const std::vector<RayMajorantSegment> segments =
        walk(DdaMajorantIterator(ray.origin, ray.dir, 0.0f, 1000.0f, majorants, sigma_t));
    if (!hits) {
      EXPECT_TRUE(segments.empty());
      continue;
    }
    ASSERT_FALSE(segments.empty());
    ++walked;
    EXPECT_EQ(segments.front().t_min, t0);
    EXPECT_EQ(segments.back().t_max, t1);
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const RayMajorantSegment& s = segments[i];
      EXPECT_LT(s.t_min, s.t_max);
      if (i > 0) {
        EXPECT_EQ(s.t_min, segments[i - 1].t_max);
      }
      // The segment carries the majorant of the cell its middle lies in (away from cell faces,
      // where either neighbour is right).
      const Vec3 mid = ray.origin + ray.dir * (0.5f * (s.t_min + s.t_max));
      int cell[3];
      bool near_face = false;
      for (int a = 0; a < 3; ++a) {
        const float width = (majorants.bounds().upper[a] - majorants.bounds().lower[a]) / majorants.resolution()[a];
        const float c = (mid[a] - majorants.bounds().lower[a]) / width;
        cell[a] = std::clamp(static_cast<int>(std::floor(c)), 0, majorants.resolution()[a] - 1);
        near_face = near_face || std::fabs(c - std::round(c)) < 1e-3f;
      }
      if (!near_face) {
        EXPECT_EQ(s.sigma_maj, sigma_t * majorants.at(cell[0], cell[1], cell[2]));
      }
    }
    // Skipping empty cells leaves exactly the segments with a non-zero majorant.
    std::vector<RayMajorantSegment> nonzero;
    for (const RayMajorantSegment& s : segments)
      if (s.sigma_maj > 0.0f) nonzero.push_back(s);
    const auto skipped = walk(DdaMajorantIterator(ray.origin, ray.dir, 0.0f, 1000.0f, majorants, sigma_t, true));
    ASSERT_EQ(skipped.size(), nonzero.size());
    for (std::size_t i = 0; i < skipped.size(); ++i) {
      EXPECT_EQ(skipped[i].t_min, nonzero[i].t_min);
      EXPECT_EQ(skipped[i].t_max, nonzero[i].t_max);
    }
  }
  EXPECT_GT(walked, 900);
}

TEST(DdaMajorantIterator, RaysThatMissTheGridOrEndBeforeItYieldNothing) {
  const VoxelGrid grid = test::random_cloud(0, 15, 0.2, 1);
  const MajorantGrid majorants(grid);
  EXPECT_FALSE(DdaMajorantIterator({-50, 0, 0}, {0, 1, 0}, 0, 1e30f, majorants, 1.0f).next());
  EXPECT_FALSE(DdaMajorantIterator({-50, 5, 5}, {1, 0, 0}, 0, 10.0f, majorants, 1.0f).next());
  EXPECT_FALSE(DdaMajorantIterator().next());
}

// Ratio tracking (Novák et al. 2014) through the majorant segments: the estimator a shadow ray
// uses, against exp(−∫σ_t) integrated along the ray by the midpoint rule.
double ratio_tracking(const VoxelGrid& grid, const MajorantGrid& majorants, const TestRay& ray, float sigma_scale,
                      std::mt19937& random) {
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  DdaMajorantIterator it(ray.origin, ray.dir, 0.0f, 1e30f, majorants, sigma_scale, true);
  double transmittance = 1.0;
  while (const auto segment = it.next()) {
    const double sigma_maj = segment->sigma_maj;
    double t = segment->t_min;
    while (true) {
      t -= std::log(1.0 - uniform(random)) / sigma_maj;
      if (t >= segment->t_max) break;
      const double sigma = sigma_scale * grid.lookup(ray.origin + ray.dir * static_cast<float>(t));
      transmittance *= 1.0 - sigma / sigma_maj;
    }
  }
  return transmittance;
}

double quadrature(const VoxelGrid& grid, const TestRay& ray, float sigma_scale, float t0, float t1) {
  constexpr int kSteps = 20000;
  const double dt = (double{t1} - t0) / kSteps;
  double optical_depth = 0.0;
  for (int i = 0; i < kSteps; ++i)
    optical_depth += sigma_scale * grid.lookup(ray.origin + ray.dir * static_cast<float>(t0 + (i + 0.5) * dt)) * dt;
  return std::exp(-optical_depth);
}

TEST(DdaMajorantIterator, RatioTrackingThroughTheSegmentsGivesTheTransmittance) {
  const VoxelGrid grid = test::random_cloud(0, 31, 0.3, 9);
  const MajorantGrid majorants(grid);
  std::mt19937 random(17);
  const std::vector<TestRay> rays = test_rays(majorants, 13);
  int compared = 0;
  for (std::size_t r = 0; r < rays.size() && compared < 8; r += 25) {
    const TestRay& ray = rays[r];
    float t0 = 0.0f, t1 = 1e30f;
    if (!clip_to_box(ray.origin, ray.dir, majorants.bounds(), t0, t1) || t1 - t0 < 5.0f) continue;
    const float sigma_scale = 0.5f;
    const double expected = quadrature(grid, ray, sigma_scale, t0, t1);
    constexpr int kSamples = 2000;
    double sum = 0.0, sum_sq = 0.0;
    for (int i = 0; i < kSamples; ++i) {
      const double estimate = ratio_tracking(grid, majorants, ray, sigma_scale, random);
      sum += estimate;
      sum_sq += estimate * estimate;
    }
    const double mean = sum / kSamples;
    const double sigma = std::sqrt(std::max(0.0, sum_sq / kSamples - mean * mean) / kSamples);
    EXPECT_NEAR(mean, expected, 5.0 * sigma + 1e-3) << "ray " << r << ", optical depth " << -std::log(expected);
    ++compared;
  }
  EXPECT_EQ(compared, 8);
}

}  // namespace majorant_iterator_test
}  // namespace rtpro
