// The packet form of the sphere intersector must answer what intersect_sphere answers, bit for
// bit, lane by lane: Embree's sphere callbacks use it, and top-level sphere hits are promised to
// be identical between the backends.
#include "sphere_lanes.h"

#include "rtpro/core/fp_env.h"
#include "rtpro/geometry/sphere_intersect.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace rtpro {
namespace sphere_lanes_test {

struct LaneRay {
  Vec3 org, dir;
  float tnear, tfar;
};

// Rays of every kind the renderer sends and a few it should never send: through the sphere, from
// inside it, starting on it and leaving (shadow rays), grazing it, segments ending before it,
// negative tnear, zero and NaN directions, huge and tiny coordinates.
LaneRay random_lane_ray(std::mt19937& rng, const Vec3& center, float radius) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 9);
  const Vec3 random_dir{unit(rng), unit(rng), unit(rng)};
  LaneRay ray{Vec3{unit(rng), unit(rng), unit(rng)} * (4.0f * radius) + center, random_dir, 0.0f,
              std::numeric_limits<float>::infinity()};
  switch (kind(rng)) {
    case 0: ray.dir = center - ray.org + Vec3{unit(rng), unit(rng), unit(rng)} * (0.3f * radius); break;
    case 1: ray.org = center + random_dir * (0.5f * radius); break;  // inside
    case 2: {                                                        // on the surface, leaving or entering
      const Vec3 n = normalize(random_dir);
      ray.org = center + n * radius;
      ray.dir = n * unit(rng) + Vec3{unit(rng), unit(rng), unit(rng)} * 0.2f;
      break;
    }
    case 3: {  // grazing: aimed at a point just off the silhouette
      const Vec3 n = normalize(random_dir);
      const Vec3 side = normalize(cross(n, Vec3(0.3f, 1.0f, 0.1f)));
      ray.org = center + n * (5.0f * radius) + side * (radius * (1.0f + 1e-7f * unit(rng)));
      ray.dir = -n;
      break;
    }
    case 4: ray.tfar = std::fabs(unit(rng)) * 3.0f * radius; break;  // a segment
    case 5: ray.tnear = -std::fabs(unit(rng)) * radius; break;
    case 6: ray.dir = Vec3(0.0f); break;
    case 7: ray.dir.y = std::numeric_limits<float>::quiet_NaN(); break;
    case 8:
      ray.org = ray.org * 1e6f;
      ray.dir = center - ray.org;
      break;  // far away, small sphere
    default: break;
  }
  return ray;
}

// Runs `count` lanes through intersect_sphere_lanes and checks each against the scalar function.
void expect_lanes_match(const Vec3& center, float radius, const std::vector<LaneRay>& rays, std::uint32_t active) {
  const auto count = static_cast<unsigned>(rays.size());
  std::array<std::vector<float>, 8> fields;
  for (auto& f : fields) f.resize(count);
  for (unsigned i = 0; i < count; ++i) {
    fields[0][i] = rays[i].org.x;
    fields[1][i] = rays[i].org.y;
    fields[2][i] = rays[i].org.z;
    fields[3][i] = rays[i].dir.x;
    fields[4][i] = rays[i].dir.y;
    fields[5][i] = rays[i].dir.z;
    fields[6][i] = rays[i].tnear;
    fields[7][i] = rays[i].tfar;
  }
  const RayLanes lanes{fields[0].data(), fields[1].data(), fields[2].data(),
                       fields[3].data(), fields[4].data(), fields[5].data(),
                       fields[6].data(), fields[7].data(), count};
  constexpr float kUntouched = -12345.0f;
  std::vector<float> t(count, kUntouched);
  const std::uint32_t hits = intersect_sphere_lanes(center, radius, lanes, active, t.data());
  for (unsigned i = 0; i < count; ++i) {
    const bool is_active = active >> i & 1u;
    float expected_t = kUntouched;
    const bool expected = is_active && intersect_sphere(center, radius, rays[i].org, rays[i].dir, rays[i].tnear,
                                                        rays[i].tfar, expected_t);
    ASSERT_EQ(bool(hits >> i & 1u), expected) << "lane " << i;
    if (expected)
      EXPECT_EQ(std::bit_cast<std::uint32_t>(t[i]), std::bit_cast<std::uint32_t>(expected_t)) << "lane " << i;
    else EXPECT_EQ(t[i], kUntouched) << "lane " << i << " was written without a hit";
  }
}

TEST(SphereLanes, EveryLaneAnswersWhatTheScalarIntersectorAnswers) {
  set_tracing_fp_mode();
  std::mt19937 rng(2024);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits_seen = 0;
  for (int round = 0; round < 4000; ++round) {
    const Vec3 center = Vec3{unit(rng), unit(rng), unit(rng)} * (round % 3 == 0 ? 1000.0f : 3.0f);
    const float radius = round % 5 == 0 ? 1000.0f : 0.01f + std::fabs(unit(rng));
    const unsigned count = (round % 3 == 0) ? 4u : (round % 3 == 1 ? 8u : 16u);
    std::vector<LaneRay> rays;
    for (unsigned i = 0; i < count; ++i) rays.push_back(random_lane_ray(rng, center, radius));
    const std::uint32_t all = count == 32 ? ~0u : (1u << count) - 1u;
    const std::uint32_t active = round % 4 == 0 ? all : (static_cast<std::uint32_t>(rng()) & all);
    expect_lanes_match(center, radius, rays, active);
    for (unsigned i = 0; i < count; ++i) {
      float t;
      hits_seen += (active >> i & 1u) &&
                   intersect_sphere(center, radius, rays[i].org, rays[i].dir, rays[i].tnear, rays[i].tfar, t);
    }
    if (HasFatalFailure()) return;
  }
  // The rays must exercise hits and misses alike.
  EXPECT_GT(hits_seen, 5000);
  EXPECT_LT(hits_seen, 30000);
}

TEST(SphereLanes, OddLaneCountsAndSingleRaysWork) {
  set_tracing_fp_mode();
  std::mt19937 rng(7);
  const Vec3 center{0.5f, -0.25f, 2.0f};
  for (unsigned count : {1u, 2u, 3u, 5u}) {
    std::vector<LaneRay> rays;
    for (unsigned i = 0; i < count; ++i) rays.push_back(random_lane_ray(rng, center, 0.7f));
    expect_lanes_match(center, 0.7f, rays, (1u << count) - 1u);
  }
}

}  // namespace sphere_lanes_test
}  // namespace rtpro
