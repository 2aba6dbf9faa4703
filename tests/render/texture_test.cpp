// Material colour textures: a constant colour, and the world-space checkerboard.
#include "texture.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace texture_test {

const Color kEven{0.9f, 0.8f, 0.7f}, kOdd{0.1f, 0.2f, 0.3f};

CheckerTexture checker(float size, CheckerAxes axes) { return {1.0f / size, kEven, kOdd, axes}; }

SurfacePoint at(const Vec3& position) {
  SurfacePoint point{};
  point.position = position;
  return point;
}

TEST(Texture, AConstantColourIsTheSameEverywhere) {
  const ColorTexture texture = Color{0.25f, 0.5f, 0.75f};
  EXPECT_EQ(evaluate(texture, at({0, 0, 0}), nullptr), (Color{0.25f, 0.5f, 0.75f}));
  EXPECT_EQ(evaluate(texture, at({-3e5f, 7, 1e-9f}), nullptr), (Color{0.25f, 0.5f, 0.75f}));
}

TEST(Texture, CheckerSquaresAlternateOnBothSidesOfZero) {
  const ColorTexture texture = checker(2.0f, CheckerAxes::kXZ);
  EXPECT_EQ(evaluate(texture, at({0.5f, 0, 0.5f}), nullptr), kEven);
  EXPECT_EQ(evaluate(texture, at({2.5f, 0, 0.5f}), nullptr), kOdd);
  EXPECT_EQ(evaluate(texture, at({2.5f, 0, 2.5f}), nullptr), kEven);
  // Squares keep their size across zero: [-2, 0) is one square, odd next to [0, 2).
  EXPECT_EQ(evaluate(texture, at({-0.5f, 0, 0.5f}), nullptr), kOdd);
  EXPECT_EQ(evaluate(texture, at({-1.9f, 0, 0.5f}), nullptr), kOdd);
  EXPECT_EQ(evaluate(texture, at({-2.1f, 0, 0.5f}), nullptr), kEven);
}

TEST(Texture, APlanarCheckerIgnoresTheThirdAxis) {
  // A ground plane at y = 0 whose points round to either side of zero keeps one colour per square.
  const ColorTexture ground = checker(1.0f, CheckerAxes::kXZ);
  EXPECT_EQ(evaluate(ground, at({0.5f, 1e-6f, 0.5f}), nullptr), evaluate(ground, at({0.5f, -1e-6f, 0.5f}), nullptr));
  const ColorTexture wall = checker(1.0f, CheckerAxes::kXY);
  EXPECT_EQ(evaluate(wall, at({0.5f, 0.5f, 3.7f}), nullptr), evaluate(wall, at({0.5f, 0.5f, -8.2f}), nullptr));
  const ColorTexture side = checker(1.0f, CheckerAxes::kYZ);
  EXPECT_EQ(evaluate(side, at({10.5f, 0.5f, 0.5f}), nullptr), evaluate(side, at({-4.5f, 0.5f, 0.5f}), nullptr));
}

TEST(Texture, ASolidCheckerAlternatesAlongEveryAxis) {
  const ColorTexture solid = checker(1.0f, CheckerAxes::kXYZ);
  EXPECT_EQ(evaluate(solid, at({0.5f, 0.5f, 0.5f}), nullptr), kEven);
  EXPECT_EQ(evaluate(solid, at({0.5f, 1.5f, 0.5f}), nullptr), kOdd);
  EXPECT_EQ(evaluate(solid, at({1.5f, 1.5f, 0.5f}), nullptr), kEven);
  EXPECT_EQ(evaluate(solid, at({1.5f, 1.5f, 1.5f}), nullptr), kOdd);
}

}  // namespace texture_test
}  // namespace rtpro
