// The shading frame: orthonormal and right-handed for every normal, including the poles where
// naive constructions divide by zero, and to_world undoes to_local.
#include "shading_frame.h"

#include "bsdf_test_support.h"

#include <gtest/gtest.h>

#include <vector>

namespace rtpro {
namespace shading_frame_test {

std::vector<Vec3> test_normals() {
  std::vector<Vec3> normals{{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, normalize(Vec3{1e-4f, 0, -1})};
  test::Uniforms uniforms(3);
  for (int i = 0; i < 1000; ++i) normals.push_back(uniforms.next_direction());
  return normals;
}

TEST(ShadingFrame, IsOrthonormalAndRightHanded) {
  for (const Vec3& n : test_normals()) {
    const ShadingFrame frame = ShadingFrame::from_normal(n);
    EXPECT_NEAR(length(frame.s), 1.0f, 1e-5f);
    EXPECT_NEAR(length(frame.t), 1.0f, 1e-5f);
    EXPECT_NEAR(dot(frame.s, frame.t), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(frame.s, n), 0.0f, 1e-5f);
    EXPECT_NEAR(dot(frame.t, n), 0.0f, 1e-5f);
    const Vec3 c = cross(frame.s, frame.t);
    EXPECT_NEAR(c.x, n.x, 1e-5f);
    EXPECT_NEAR(c.y, n.y, 1e-5f);
    EXPECT_NEAR(c.z, n.z, 1e-5f);
  }
}

TEST(ShadingFrame, NormalBecomesZAndRoundTrips) {
  const Vec3 v = normalize(Vec3{0.3f, -0.5f, 0.8f});
  for (const Vec3& n : test_normals()) {
    const ShadingFrame frame = ShadingFrame::from_normal(n);
    EXPECT_NEAR(frame.to_local(n).z, 1.0f, 1e-5f);
    const Vec3 back = frame.to_world(frame.to_local(v));
    EXPECT_NEAR(back.x, v.x, 1e-5f);
    EXPECT_NEAR(back.y, v.y, 1e-5f);
    EXPECT_NEAR(back.z, v.z, 1e-5f);
    EXPECT_NEAR(frame.to_local(v).z, dot(v, n), 1e-5f);  // cos θ is the local z
  }
}

}  // namespace shading_frame_test
}  // namespace rtpro
