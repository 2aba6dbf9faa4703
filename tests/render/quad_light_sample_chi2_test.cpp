// A quad light's samples against its pdf, seen from far, grazing and just above it
// (light_set_chi2_support.h).
#include "light_set_chi2_support.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace quad_light_sample_chi2_test {

using namespace light_set_test;

TEST(LightSetChi2, QuadLightSamplerMatchesPdf) {
  TestScene scene;
  scene.add_quad_light(kQuadCorner, kQuadEdge1, kQuadEdge2, Color(4.0f, 3.0f, 2.0f));
  const Vec3 normal = normalize(cross(kQuadEdge1, kQuadEdge2));
  const Vec3 middle = kQuadCorner + (kQuadEdge1 + kQuadEdge2) * 0.5f;
  expect_light_sampler_matches_pdf("quad light", scene,
                                   {{"far", Vec3(-3.0f, 0.5f, 1.5f)},
                                    {"grazing", Vec3(1.0f, 2.5f, -1.0f)},
                                    {"0.02 above its middle", middle + normal * 0.02f}});
}

}  // namespace quad_light_sample_chi2_test
}  // namespace rtpro
