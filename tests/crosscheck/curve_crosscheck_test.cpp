// Curves on both backends: Embree's own round and flat curves against the native intersector's
// pieces (src/backend/curve_intersect.h), held to the tolerance docs/backends.md states.
#include "rtpro/backend/backend.h"
#include "rtpro/crosscheck/crosscheck.h"
#include "rtpro/scene/curve_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace rtpro {
namespace curve_crosscheck_test {

// `strands` random strands of 5 points each, wandering from random roots, with radii of 0.5% to
// 3% of the scene's size.
CurveSet random_curves(std::mt19937& rng, int strands, CurveBasis basis, CurveShape shape) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_real_distribution<float> radius(0.01f, 0.06f);
  // The draws one statement each: the order of a call's arguments is unspecified (gcc and clang
  // differ), and the scene must be the same under both.
  const auto random_vec = [&] {
    const float x = unit(rng);
    const float y = unit(rng);
    const float z = unit(rng);
    return Vec3(x, y, z);
  };
  std::vector<CurvePoint> points;
  std::vector<std::uint32_t> counts;
  const int per_strand = basis == CurveBasis::kBezier ? 7 : 5;
  for (int s = 0; s < strands; ++s) {
    Vec3 p = random_vec();
    const Vec3 heading = normalize(random_vec());
    for (int i = 0; i < per_strand; ++i) {
      points.push_back({p, radius(rng)});
      p += (heading + random_vec() * 0.4f) * 0.25f;
    }
    counts.push_back(per_strand);
  }
  CurveSet curves = curves_from_strands(std::move(points), counts, basis);
  curves.shape = shape;
  return curves;
}

RenderScene scene_of(CurveSet curves) {
  RenderScene scene;
  scene.materials.emplace_back();
  scene.material_names.push_back("default");
  scene.camera.position = Vec3(0.0f, 0.0f, -4.0f);
  scene.top.geometries.emplace_back(std::move(curves));
  return scene;
}

std::string summary(const CrosscheckReport& r) {
  std::string text = "identical " + std::to_string(r.identical) + ", within tolerance " +
                     std::to_string(r.within_tolerance) + ", ambiguous " + std::to_string(r.ambiguous) +
                     ", mismatches " + std::to_string(r.mismatches) + ", occlusion mismatches " +
                     std::to_string(r.occlusion_mismatches);
  for (const CrosscheckCase& c : r.worst)
    text += "\n  ray " + std::to_string(c.index) + ": " + c.note + " native t " + std::to_string(c.reference.t) +
            " prim " + std::to_string(c.reference.prim_id) + " u " + std::to_string(c.reference.u) + " v " +
            std::to_string(c.reference.v) + " | embree t " + std::to_string(c.candidate.t) + " prim " +
            std::to_string(c.candidate.prim_id) + " u " + std::to_string(c.candidate.u) + " v " +
            std::to_string(c.candidate.v);
  return text;
}

struct Case {
  CurveBasis basis;
  CurveShape shape;
};

class CurveCrosscheck : public ::testing::TestWithParam<Case> {};

TEST_P(CurveCrosscheck, BackendsAgreeWithinTheStatedTolerance) {
  std::mt19937 rng(7);
  const RenderScene scene = scene_of(random_curves(rng, 60, GetParam().basis, GetParam().shape));
  const auto native = make_backend(BackendKind::kNative, scene, {});
  const auto embree = make_backend(BackendKind::kEmbree, scene, {});
  CrosscheckOptions options;
  options.rays = 4000;
  options.seed = 3;
  const CrosscheckReport report = crosscheck(scene, *native, *embree, options);
  EXPECT_TRUE(report.passed()) << summary(report);
  // The rays meet the curves often enough for the agreement to mean something.
  EXPECT_GT(report.within_tolerance, 150u) << summary(report);
  EXPECT_LT(report.ambiguous, 60u) << summary(report);
}

INSTANTIATE_TEST_SUITE_P(
    Bases, CurveCrosscheck,
    ::testing::Values(Case{CurveBasis::kLinear, CurveShape::kRound}, Case{CurveBasis::kCatmullRom, CurveShape::kRound},
                      Case{CurveBasis::kBSpline, CurveShape::kRound}, Case{CurveBasis::kBezier, CurveShape::kRound},
                      Case{CurveBasis::kLinear, CurveShape::kFlat}, Case{CurveBasis::kCatmullRom, CurveShape::kFlat},
                      Case{CurveBasis::kBSpline, CurveShape::kFlat}));

}  // namespace curve_crosscheck_test
}  // namespace rtpro
