// The packet's wide load must hold exactly what eight set() calls hold, and must refuse a group of
// eight exactly when the backend's own admission test (is_traceable) refuses one of its rays:
// otherwise an untraceable ray would reach the traversal, or a rejected ray go uncounted.
#include "ray_packet.h"
#include "ray_gate.h"

#include "rtpro/core/ray.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace rtpro {
namespace ray_packet_test {

// A ray the renderer would send, or, with probability `broken`, one with a single bad field of the
// kinds is_traceable refuses (and a few it accepts that look suspicious: -0 tnear, zero tfar).
Ray random_ray(std::mt19937& rng, float broken) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), chance(0.0f, 1.0f);
  Ray ray{Vec3{unit(rng), unit(rng), unit(rng)} * 100.0f, std::abs(unit(rng)) * 1e-3f,
          Vec3{unit(rng), unit(rng), unit(rng)}, chance(rng) < 0.5f ? std::numeric_limits<float>::infinity() : 50.0f};
  if (!(chance(rng) < broken)) return ray;
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN(), kInf = std::numeric_limits<float>::infinity();
  std::uniform_int_distribution<int> kind(0, 13);
  switch (kind(rng)) {
    case 0: ray.org.x = kNaN; break;
    case 1: ray.org.y = -kInf; break;
    case 2: ray.org.z = kMaxTraceableMagnitude; break;
    case 3: ray.dir.x = 2e16f; break;
    case 4: ray.dir.y = kNaN; break;
    case 5: ray.dir = Vec3(0.0f, -0.0f, 0.0f); break;
    case 6: ray.tnear = -1e-7f; break;
    case 7: ray.tnear = kInf; break;
    case 8: ray.tnear = kNaN; break;
    case 9: ray.tfar = kNaN; break;
    case 10: ray.tnear = 60.0f, ray.tfar = 50.0f; break;
    case 11: ray.tnear = -0.0f; break;                                         // accepted
    case 12: ray.tnear = 0.0f, ray.tfar = 0.0f; break;                         // accepted
    case 13: ray.org.x = std::nextafter(kMaxTraceableMagnitude, 0.0f); break;  // accepted
  }
  return ray;
}

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

// The gate's two-compare test must admit exactly the rays the scalar is_traceable admits, at every
// boundary random_ray exercises (NaN, infinities, the magnitude limit and the float below it,
// negative and -0 tnear, an empty segment, a zero direction).
TEST(RayGate, AdmitsExactlyTheRaysIsTraceableAdmits) {
  std::mt19937 rng(11);
  int accepted = 0, refused = 0;
  for (int round = 0; round < 50000; ++round) {
    const Ray ray = random_ray(rng, 0.5f);
    const bool expected = is_traceable(ray);
    ASSERT_EQ(is_traceable_ray(ray), expected) << "round " << round;
    (expected ? accepted : refused) += 1;
  }
  EXPECT_GT(accepted, 20000);
  EXPECT_GT(refused, 15000);
}

TEST(RayPacket, WideLoadHoldsWhatEightSetsHoldAndRefusesExactlyWhatIsTraceableRefuses) {
  if (!sphere_lanes_vectorised()) GTEST_SKIP() << "no AVX2 on this machine: packets are not used";
  std::mt19937 rng(7);
  int accepted = 0, refused = 0;
  for (int round = 0; round < 20000; ++round) {
    std::array<Ray, kPacketSize> rays;
    const float broken = round % 2 == 0 ? 0.0f : 0.05f;
    for (Ray& ray : rays) ray = random_ray(rng, broken);
    bool all_traceable = true;
    for (const Ray& ray : rays) all_traceable = all_traceable && is_traceable(ray);

    RayPacket wide;
    const bool loaded = wide.load_traceable(rays.data());
    ASSERT_EQ(loaded, all_traceable) << "round " << round;
    if (!loaded) {
      ++refused;
      continue;
    }
    ++accepted;
    RayPacket scalar;
    for (unsigned lane = 0; lane < kPacketSize; ++lane) scalar.set(lane, rays[lane], rays[lane].tfar);
    scalar.finish(kPacketSize);
    for (unsigned lane = 0; lane < kPacketSize; ++lane) {
      SCOPED_TRACE(testing::Message() << "round " << round << " lane " << lane);
      EXPECT_EQ(wide.rays[lane], &rays[lane]);
      const std::array<std::pair<const float*, const float*>, 11> fields = {{{wide.org_x, scalar.org_x},
                                                                             {wide.org_y, scalar.org_y},
                                                                             {wide.org_z, scalar.org_z},
                                                                             {wide.dir_x, scalar.dir_x},
                                                                             {wide.dir_y, scalar.dir_y},
                                                                             {wide.dir_z, scalar.dir_z},
                                                                             {wide.inv_x, scalar.inv_x},
                                                                             {wide.inv_y, scalar.inv_y},
                                                                             {wide.inv_z, scalar.inv_z},
                                                                             {wide.tnear, scalar.tnear},
                                                                             {wide.tmax, scalar.tmax}}};
      for (const auto& [w, s] : fields) EXPECT_TRUE(same_bits(w[lane], s[lane])) << w[lane] << " vs " << s[lane];
    }
  }
  // Both outcomes were exercised many times.
  EXPECT_GT(accepted, 10000);
  EXPECT_GT(refused, 2000);
}

}  // namespace ray_packet_test
}  // namespace rtpro
