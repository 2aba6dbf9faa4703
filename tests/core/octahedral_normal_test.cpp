#include "rtpro/core/octahedral_normal.h"

#include <gtest/gtest.h>

#include <random>

namespace rtpro {
namespace octahedral_normal_test {

double angle(const Vec3& a, const Vec3& b) {
  const Vec3 c = cross(a, b);
  return std::atan2(double(length(c)), double(dot(a, b)));
}

TEST(OctahedralNormal, EveryDirectionComesBackWithin5e5Radians) {
  std::mt19937 rng(7);
  std::normal_distribution<float> gauss;
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 n = normalize(Vec3(gauss(rng), gauss(rng), gauss(rng)));
    const Vec3 back = decode_octahedral(encode_octahedral(n));
    EXPECT_NEAR(length(back), 1.0f, 1e-6f);
    worst = std::max(worst, angle(n, back));
  }
  EXPECT_LT(worst, 5e-5);
  EXPECT_GT(worst, 1e-7);  // 32 bits cannot hold a float direction exactly: the test measures something
}

TEST(OctahedralNormal, AxesFoldsAndSeamsKeepTheirSigns) {
  const Vec3 cases[] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},          {0, -1, 0},         {0, 0, 1},
                        {0, 0, -1}, {1, 1, 0},  {-1, 0.0f, -1e-7f}, {0.0f, -1, -1e-7f}, {-1, -1, -1}};
  for (const Vec3& v : cases) {
    const Vec3 n = normalize(v);
    const Vec3 back = decode_octahedral(encode_octahedral(n));
    EXPECT_LT(angle(n, back), 5e-5) << n.x << " " << n.y << " " << n.z;
    for (int k = 0; k < 3; ++k) {
      if (std::fabs(n[k]) > 1e-3f) {
        EXPECT_EQ(std::signbit(back[k]), std::signbit(n[k])) << k;
      }
    }
  }
}

TEST(OctahedralNormal, DecodingIsAFunctionOfTheCodeAlone) {
  // Every code decodes to a unit vector, and re-encoding a decoded code gives that code back
  // (the encoder's search includes it and nothing decodes closer).
  std::mt19937 rng(11);
  for (int i = 0; i < 20000; ++i) {
    const std::uint32_t code = rng();
    if ((code & 0xFFFFu) == 0x8000u || (code >> 16) == 0x8000u) continue;  // -32768: clamped to -1, an alias
    const Vec3 n = decode_octahedral(code);
    ASSERT_NEAR(length(n), 1.0f, 1e-6f);
    EXPECT_LT(angle(decode_octahedral(encode_octahedral(n)), n), 1e-6);
  }
}

}  // namespace octahedral_normal_test
}  // namespace rtpro
