// The shading point of a curve hit on both backends: a unit fibre direction across the normal,
// pbrt's h across the fibre, and secondary rays that never re-hit the fibre they leave (hair is
// thin: the offset rule must clear it whichever way the ray goes, through it included).
#include "ray_offset.h"

#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/scene/curve_basis.h"
#include "surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace rtpro {
namespace curve_surface_test {

// Straight strands along x at z = 0, y = 0.3·i, radius 0.02, one geometry per shape and basis.
RenderScene fibre_scene(CurveBasis basis, CurveShape shape) {
  std::vector<CurvePoint> points;
  std::vector<std::uint32_t> strands;
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 5; ++k) points.push_back({Vec3(-1.0f + 0.5f * float(k), 0.3f * float(i), 0.0f), 0.02f});
    strands.push_back(5);
  }
  CurveSet curves = curves_from_strands(points, strands, basis);
  curves.shape = shape;
  RenderScene scene;
  scene.materials.emplace_back();
  scene.material_names.push_back("default");
  scene.top.geometries.emplace_back(std::move(curves));
  return scene;
}

struct Case {
  CurveBasis basis;
  CurveShape shape;
  BackendKind backend;
};

class CurveSurface : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }
};

TEST_P(CurveSurface, FibreFrameAndOffsetAcrossTheFibre) {
  const RenderScene scene = fibre_scene(GetParam().basis, GetParam().shape);
  const auto backend = make_backend(GetParam().backend, scene, {});
  // Rays down -z at offsets d across the fibre at y = 0.3: h = d / r, up to the sign convention
  // (h along cross(tangent, ray)), the same on both shapes.
  for (const float d : {-0.015f, -0.005f, 0.0f, 0.01f, 0.018f}) {
    Ray ray{Vec3(0.1f, 0.3f + d, 3.0f), 0.0f, Vec3(0.0f, 0.0f, -1.0f), INFINITY};
    Hit hit;
    ASSERT_TRUE(backend->intersect(ray, hit)) << d;
    const SurfacePoint sp = make_surface(scene, ray, hit);
    EXPECT_NEAR(length(sp.tangent), 1.0f, 1e-5f);
    EXPECT_NEAR(std::fabs(sp.tangent.x), 1.0f, 1e-4f);
    EXPECT_NEAR(dot(sp.tangent, sp.geometric_normal), 0.0f, 1e-3f);
    EXPECT_GT(dot(sp.geometric_normal, ray.dir * -1.0f), 0.0f);
    // cross((±1, 0, 0), (0, 0, -1)) is (0, ±1, 0): h = d/r along +x.
    EXPECT_NEAR(sp.fiber_offset, d / 0.02f * sp.tangent.x, 0.03f) << d;
    // The hair BSDF's own h on a round tube, from its frame (x the fibre, z the normal): −wo·y over
    // wo's length across the fibre. A sign apart from it put the R highlight on the wrong side.
    if (GetParam().shape == CurveShape::kRound) {
      const Vec3 wo = ray.dir * -1.0f;
      const Vec3 y = cross(sp.geometric_normal, sp.tangent);
      EXPECT_NEAR(sp.fiber_offset, -dot(wo, y) / length(cross(sp.tangent, wo)), 0.03f) << d;
    }
  }
}

TEST_P(CurveSurface, SpawnedRaysNeverReHitTheFibre) {
  const RenderScene scene = fibre_scene(GetParam().basis, GetParam().shape);
  const auto backend = make_backend(GetParam().backend, scene, {});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    // From a sphere of origins around the strands towards points near one of them.
    const Vec3 target{unit(rng) * 0.9f, 0.3f * float(i % 4) + unit(rng) * 0.02f, unit(rng) * 0.02f};
    const Vec3 org = target + normalize(Vec3{unit(rng), unit(rng), unit(rng)}) * 2.0f;
    Ray ray{org, 0.0f, target - org, INFINITY};
    Hit hit;
    if (!backend->intersect(ray, hit)) continue;
    ++hits;
    const SurfacePoint sp = make_surface(scene, ray, hit);
    ASSERT_GE(sp.fiber_offset, -1.0f);
    ASSERT_LE(sp.fiber_offset, 1.0f);
    // Out into the hemisphere, back through the fibre, and along it.
    for (const Vec3& direction :
         {sp.geometric_normal, sp.geometric_normal * -1.0f, ray.dir, sp.tangent * 0.2f + sp.geometric_normal * -1.0f,
          normalize(Vec3{unit(rng), unit(rng), unit(rng)})}) {
      // The strands are straight and 0.3 apart: a ray that leaves a fibre, or a shadow ray to a
      // point far along, meets no part of that fibre again.
      for (const Ray& spawned : {spawn_ray(sp, direction), spawn_ray_to(sp, sp.position + direction * 3.0f)}) {
        Hit again;
        if (backend->intersect(spawned, again)) {
          EXPECT_NE(std::lround(
                        bezier_segment(std::get<CurveSet>(scene.top.geometries[0]), again.prim_id).at(0.5f).position.y /
                        0.3f),
                    std::lround(sp.position.y / 0.3f))
              << "ray " << i << " re-hits its fibre at t " << again.t;
        }
      }
    }
  }
  EXPECT_GT(hits, 150);
}

INSTANTIATE_TEST_SUITE_P(ShapesAndBackends, CurveSurface,
                         ::testing::Values(Case{CurveBasis::kCatmullRom, CurveShape::kRound, BackendKind::kEmbree},
                                           Case{CurveBasis::kCatmullRom, CurveShape::kRound, BackendKind::kNative},
                                           Case{CurveBasis::kLinear, CurveShape::kRound, BackendKind::kEmbree},
                                           Case{CurveBasis::kLinear, CurveShape::kRound, BackendKind::kNative},
                                           Case{CurveBasis::kBSpline, CurveShape::kFlat, BackendKind::kEmbree},
                                           Case{CurveBasis::kBSpline, CurveShape::kFlat, BackendKind::kNative}));

}  // namespace curve_surface_test
}  // namespace rtpro
