// Four surfaces' point-light shadow rays at once must be the scalar chain's, bit for bit.
#include "point_light_lanes.h"

#include "light_sample.h"
#include "ray_offset.h"
#include "test_fixtures.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace rtpro {
namespace point_light_lanes_test {

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> normal;
  for (;;) {
    const Vec3 v{normal(rng), normal(rng), normal(rng)};
    if (length(v) > 1e-3f) return normalize(v);
  }
}

SurfacePoint random_surface(std::mt19937& rng, int i) {
  std::uniform_real_distribution<float> coordinate(-50.0f, 50.0f);
  SurfacePoint s{};
  s.position = {coordinate(rng), coordinate(rng), coordinate(rng)};
  if (i % 7 == 0) s.position = {0.0f, -0.0f, 0.0f};
  s.geometric_normal = random_unit(rng);
  if (i % 5 == 0) s.geometric_normal = {0.0f, i % 2 ? 1.0f : -1.0f, 0.0f};  // zero coordinates
  s.shading_normal = i % 3 == 0 ? s.geometric_normal : random_unit(rng);
  s.position_error = i % 11 == 0 ? 1e-38f : std::fabs(coordinate(rng)) * 1e-6f;
  return s;
}

// The scalar chain of shading for one point light and one surface, against lane `k` of `lanes`.
void expect_lane_is_the_scalar_chain(const PointLight& light, const SurfacePoint& s, const Vec3& mirror,
                                     const PointLightLanes& lanes, int k) {
  const LightSample ls = sample_light(Light{light}, s.position, Sample2D{0.5f, 0.5f});
  const float n_dot_l = dot(s.shading_normal, ls.direction);
  const bool lit = !(n_dot_l <= 0.0f || dot(s.geometric_normal, ls.direction) <= 0.0f);
  ASSERT_EQ(lit, (lanes.lit >> k & 1u) != 0) << "lane " << k;
  ASSERT_EQ(bits(lanes.n_dot_l[k]), bits(n_dot_l)) << "lane " << k;
  ASSERT_EQ(bits(lanes.r_dot_l[k]), bits(dot(mirror, ls.direction))) << "lane " << k;
  ASSERT_EQ(std::isinf(ls.distance), (lanes.infinite >> k & 1u) != 0) << "lane " << k;
  if (std::isinf(ls.distance) || !lit) return;
  const Ray expected = spawn_ray_to(s, s.position + ls.direction * ls.distance);
  Ray actual;
  store_ray(lanes, static_cast<unsigned>(k), actual);
  for (int axis = 0; axis < 3; ++axis) {
    ASSERT_EQ(bits(actual.org[axis]), bits(expected.org[axis])) << "lane " << k << " origin axis " << axis;
    ASSERT_EQ(bits(actual.dir[axis]), bits(expected.dir[axis])) << "lane " << k << " direction axis " << axis;
  }
  ASSERT_EQ(bits(actual.tnear), bits(expected.tnear));
  ASSERT_EQ(bits(actual.tfar), bits(expected.tfar));
}

void expect_lanes_are_the_scalar_chain() {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> coordinate(-60.0f, 60.0f);
  int lit = 0;
  for (int round = 0; round < 20000; ++round) {
    PointLight light{{coordinate(rng), coordinate(rng), coordinate(rng)}, {0.7f, 0.8f, 0.9f}};
    if (round % 97 == 0) light.position = {3e19f, -2e19f, 1e19f};  // the distance overflows
    SurfacePoint surfaces[4];
    Vec3 mirrors[4];
    const SurfacePoint* surface_ptrs[4];
    const Vec3* mirror_ptrs[4];
    for (int k = 0; k < 4; ++k) {
      surfaces[k] = random_surface(rng, round * 4 + k);
      if (round % 89 == 0 && k == 2) surfaces[k].position = light.position;  // a light on the surface
      mirrors[k] = random_unit(rng);
      surface_ptrs[k] = &surfaces[k];
      mirror_ptrs[k] = &mirrors[k];
    }
    // Two lights read the surfaces once; a null light (one of another kind) is skipped.
    const PointLight other{{coordinate(rng), coordinate(rng), coordinate(rng)}, {0.2f, 0.3f, 0.4f}};
    const PointLight* lights[3] = {&light, nullptr, &other};
    PointLightLanes lanes[3];
    lanes[1].lit = 0xA5u;
    Vec3 front_origins[4];
    point_light_lanes(lights, surface_ptrs, mirror_ptrs, lanes, front_origins);
    EXPECT_EQ(lanes[1].lit, 0xA5u);
    for (int k = 0; k < 4; ++k) {
      const Vec3 front = offset_ray_origin_on_side(surfaces[k], true);
      for (int axis = 0; axis < 3; ++axis)
        ASSERT_EQ(bits(front_origins[k][axis]), bits(front[axis])) << "lane " << k << " front origin axis " << axis;
      expect_lane_is_the_scalar_chain(light, surfaces[k], mirrors[k], lanes[0], k);
      expect_lane_is_the_scalar_chain(other, surfaces[k], mirrors[k], lanes[2], k);
      if (::testing::Test::HasFatalFailure()) return;
    }
    lit += std::popcount(lanes[0].lit);
  }
  EXPECT_GT(lit, 15000);  // both outcomes are exercised
  EXPECT_LT(lit, 65000);
}

TEST(PointLightLanes, EveryLaneIsTheScalarChainBitForBit) { expect_lanes_are_the_scalar_chain(); }

// Lights grazing the surfaces: a lit lane whose rounded target lies behind the geometric normal
// leaves by the back, while the other lanes leave by the front.
TEST(PointLightLanes, LitLanesWhoseTargetRoundsBehindLeaveByTheBack) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int by_the_back = 0;
  for (int round = 0; round < 20000; ++round) {
    SurfacePoint surfaces[4];
    Vec3 mirrors[4];
    const SurfacePoint* surface_ptrs[4];
    const Vec3* mirror_ptrs[4];
    for (int k = 0; k < 4; ++k) {
      surfaces[k] = random_surface(rng, round * 4 + k + 1);
      surfaces[k].shading_normal = surfaces[k].geometric_normal;
      mirrors[k] = random_unit(rng);
      surface_ptrs[k] = &surfaces[k];
      mirror_ptrs[k] = &mirrors[k];
    }
    // In the tangent plane of surface 1, lifted by a few ulps of the distance.
    const SurfacePoint& s = surfaces[1];
    const Vec3 tangent = normalize(cross(s.geometric_normal, random_unit(rng)));
    const PointLight light{s.position + tangent * 30.0f + s.geometric_normal * (1e-5f * (1.0f + unit(rng))),
                           {1.0f, 1.0f, 1.0f}};
    const PointLight* lights[1] = {&light};
    PointLightLanes lanes[1];
    Vec3 front_origins[4];
    point_light_lanes(lights, surface_ptrs, mirror_ptrs, lanes, front_origins);
    for (int k = 0; k < 4; ++k) {
      expect_lane_is_the_scalar_chain(light, surfaces[k], mirrors[k], lanes[0], k);
      if (::testing::Test::HasFatalFailure()) return;
      const LightSample ls = sample_light(Light{light}, surfaces[k].position, Sample2D{0.5f, 0.5f});
      const Vec3 target = surfaces[k].position + ls.direction * ls.distance;
      if ((lanes[0].lit >> k & 1u) && !leaves_front(surfaces[k], target - surfaces[k].position)) ++by_the_back;
    }
  }
  EXPECT_GT(by_the_back, 10);  // the back origins are exercised
}

TEST(PointLightLanes, EveryLaneIsTheScalarChainUnderTheTracingFloatingPointMode) {
  test::in_tracing_fp_mode(expect_lanes_are_the_scalar_chain);
}

}  // namespace point_light_lanes_test
}  // namespace rtpro
