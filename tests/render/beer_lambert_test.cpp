// Beer–Lambert: the stated colour is reached at the stated distance, and transmittance over two
// path pieces multiplies (exponential law), so splitting a path inside glass changes nothing.
#include "beer_lambert.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rtpro {
namespace beer_lambert_test {

TEST(BeerLambert, ReachesStatedColourAtStatedDistance) {
  const Vec3 colour{0.8f, 0.5f, 0.25f};
  const Vec3 t = beer_lambert_transmittance(colour, 2.0f, 2.0f);
  EXPECT_NEAR(t.x, 0.8f, 1e-6f);
  EXPECT_NEAR(t.y, 0.5f, 1e-6f);
  EXPECT_NEAR(t.z, 0.25f, 1e-6f);
  const Vec3 none = beer_lambert_transmittance(colour, 2.0f, 0.0f);
  EXPECT_EQ(none, (Vec3{1.0f, 1.0f, 1.0f}));
}

TEST(BeerLambert, ComposesMultiplicatively) {
  const Vec3 colour{0.9f, 0.6f, 0.3f};
  const Vec3 whole = beer_lambert_transmittance(colour, 1.5f, 3.7f);
  const Vec3 a = beer_lambert_transmittance(colour, 1.5f, 1.2f);
  const Vec3 b = beer_lambert_transmittance(colour, 1.5f, 2.5f);
  EXPECT_NEAR(whole.x, a.x * b.x, 1e-6f);
  EXPECT_NEAR(whole.y, a.y * b.y, 1e-6f);
  EXPECT_NEAR(whole.z, a.z * b.z, 1e-6f);
  EXPECT_NEAR(whole.z, std::exp(-std::log(0.3f) / -1.5f * 3.7f), 1e-6f);
}

}  // namespace beer_lambert_test
}  // namespace rtpro
