// Native vs Embree on random scenes and on every shipped scene, plus proof that the checker
// itself notices a backend that is off by one ulp or loses hits.
#include "rtpro/crosscheck/crosscheck.h"

#include "rtpro/backend/backend.h"
#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"
#include "test_commands.h"
#include "test_paths.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <string>

namespace rtpro {
namespace crosscheck_test {

std::string summary(const CrosscheckReport& r) {
  std::string text = "identical " + std::to_string(r.identical) + ", within tolerance " +
                     std::to_string(r.within_tolerance) + ", ambiguous " + std::to_string(r.ambiguous) +
                     ", mismatches " + std::to_string(r.mismatches) + ", occlusion mismatches " +
                     std::to_string(r.occlusion_mismatches) + ", max t error " + std::to_string(r.max_t_error) +
                     ", max surface error " + std::to_string(r.max_surface_error);
  for (const CrosscheckCase& c : r.worst) text += "\n  ray " + std::to_string(c.index) + ": " + c.note;
  return text;
}

CrosscheckReport check_backends(const RenderScene& scene, std::size_t rays, std::uint64_t seed) {
  const auto native = make_backend(BackendKind::kNative, scene, {});
  const auto embree = make_backend(BackendKind::kEmbree, scene, {});
  CrosscheckOptions options;
  options.rays = rays;
  options.seed = seed;
  return crosscheck(scene, *native, *embree, options);
}

TEST(Crosscheck, RandomSpheresAreBitIdentical) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    RenderScene scene = test::random_mixed_scene(seed, 3000, 0, 0);
    // Small, far and overlapping spheres too: a second set around a distant point.
    std::mt19937 rng(seed);
    SphereSet far_set = test::random_spheres(rng, 500, 0.05f);
    for (Sphere& s : far_set.spheres) s.center += Vec3(300.0f, -200.0f, 900.0f);
    scene.top.geometries.emplace_back(std::move(far_set));

    const CrosscheckReport report = check_backends(scene, 20000, seed);
    EXPECT_TRUE(report.passed()) << summary(report);
    EXPECT_EQ(report.mismatches, 0u) << summary(report);
    EXPECT_EQ(report.within_tolerance, 0u) << summary(report);
    EXPECT_EQ(report.ambiguous, 0u) << summary(report);
    EXPECT_EQ(report.identical, report.rays);
    EXPECT_GT(report.top_level_sphere_hits, report.rays / 4);
    EXPECT_EQ(report.max_t_error, 0.0);
  }
}

TEST(Crosscheck, RandomTriangleSoupsAgreeWithinTolerance) {
  for (std::uint32_t seed : {4u, 5u}) {
    const RenderScene scene = test::random_mixed_scene(seed, 0, 5000, 0);
    const CrosscheckReport report = check_backends(scene, 20000, seed);
    EXPECT_TRUE(report.passed()) << summary(report);
    EXPECT_GT(report.identical + report.within_tolerance, report.rays * 9 / 10) << summary(report);
  }
}

TEST(Crosscheck, InstancedScenesAgreeWithinTolerance) {
  for (std::uint32_t seed : {6u, 7u}) {
    const RenderScene scene = test::random_mixed_scene(seed, 2000, 2000, 40);
    const CrosscheckReport report = check_backends(scene, 20000, seed);
    EXPECT_TRUE(report.passed()) << summary(report);
    EXPECT_GT(report.top_level_sphere_hits, 0u);
  }
}

// The random rays of a flat scene all start in its plane, and Embree's triangles report a hit at
// t = ±0 where rtpro's interval (tnear, tfar] is open: whether a ray hits the surface it starts on
// is rounding, not a disagreement.
TEST(Crosscheck, AOneTriangleSceneAgreesThoughRandomRaysStartOnIt) {
  RenderScene scene = test::empty_scene();
  TriangleMesh triangle;
  triangle.vertices = {{-4.0f, -3.0f, 0.0f}, {4.0f, -3.0f, 0.0f}, {0.0f, 3.0f, 0.0f}};
  triangle.triangles = {{0, 1, 2}};
  scene.top.geometries.emplace_back(std::move(triangle));
  ASSERT_EQ(scene.bounds().extent().z, 0.0f);
  const CrosscheckReport report = check_backends(scene, 1000, 1);
  EXPECT_TRUE(report.passed()) << summary(report);
  EXPECT_EQ(report.ambiguous, 0u) << summary(report);
  // Not vacuous: the camera rays that hit the triangle (a third of the view) each ask two more
  // occlusion questions, around their hit.
  EXPECT_GT(report.occlusion_queries, report.rays + report.rays / 10) << summary(report);
}

// A backend that is right except for one thing the checker must catch.
class Perturbed final : public Backend {
 public:
  enum class Fault { kSphereUlp, kLostHits };
  Perturbed(const Backend& inner, Fault fault) : inner_(inner), fault_(fault) {}
  std::string_view name() const override { return "perturbed"; }
  bool intersect(const Ray& ray, Hit& hit) const override {
    if (!inner_.intersect(ray, hit)) return false;
    if (fault_ == Fault::kLostHits) return hit.prim_id % 7 != 3;
    if (hit.inst_id == kInvalidId) hit.t = std::nextafter(hit.t, 0.0f);
    return true;
  }
  bool occluded(const Ray& ray) const override { return inner_.occluded(ray); }
  BackendStats stats() const override { return inner_.stats(); }

 private:
  const Backend& inner_;
  Fault fault_;
};

TEST(Crosscheck, NoticesAnUlpOnSpheresAndLostHits) {
  CrosscheckOptions options;
  options.rays = 5000;

  const RenderScene spheres = test::random_mixed_scene(8, 2000, 0, 0);
  const auto native_spheres = make_backend(BackendKind::kNative, spheres, {});
  const auto embree_spheres = make_backend(BackendKind::kEmbree, spheres, {});
  const CrosscheckReport ulp =
      crosscheck(spheres, *native_spheres, Perturbed(*embree_spheres, Perturbed::Fault::kSphereUlp), options);
  EXPECT_FALSE(ulp.passed());
  EXPECT_GT(ulp.mismatches, 1000u);
  ASSERT_FALSE(ulp.worst.empty());
  EXPECT_EQ(ulp.worst.front().agreement, Agreement::kMismatch);
  EXPECT_EQ(ulp.worst.front().note, "top-level sphere hit is not bit-identical");

  const RenderScene mixed = test::random_mixed_scene(8, 2000, 2000, 10);
  const auto native = make_backend(BackendKind::kNative, mixed, {});
  const auto embree = make_backend(BackendKind::kEmbree, mixed, {});
  const CrosscheckReport lost = crosscheck(mixed, *native, Perturbed(*embree, Perturbed::Fault::kLostHits), options);
  EXPECT_FALSE(lost.passed());
  EXPECT_GT(lost.mismatches, 50u);
  EXPECT_LE(lost.worst.size(), options.worst_cases);

  // And the same backend against itself is identical everywhere.
  const CrosscheckReport self = crosscheck(mixed, *embree, *embree, options);
  EXPECT_EQ(self.identical, self.rays);
}

TEST(Crosscheck, SameRaysForTheSameSeed) {
  const RenderScene scene = test::random_mixed_scene(9, 500, 500, 5);
  const auto native = make_backend(BackendKind::kNative, scene, {});
  const auto embree = make_backend(BackendKind::kEmbree, scene, {});
  CrosscheckOptions options;
  options.rays = 3000;
  const CrosscheckReport a = crosscheck(scene, *native, Perturbed(*embree, Perturbed::Fault::kLostHits), options);
  const CrosscheckReport b = crosscheck(scene, *native, Perturbed(*embree, Perturbed::Fault::kLostHits), options);
  ASSERT_EQ(a.worst.size(), b.worst.size());
  for (std::size_t i = 0; i < a.worst.size(); ++i) {
    EXPECT_EQ(a.worst[i].index, b.worst[i].index);
    EXPECT_EQ(a.worst[i].ray.dir, b.worst[i].ray.dir);
  }
  EXPECT_EQ(a.mismatches, b.mismatches);
}

TEST(Crosscheck, EveryShippedSceneAgrees) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::scenes_dir())) {
    if (entry.path().extension() != ".yaml") continue;
    if (test::uses_fetched_assets(entry.path()) && !test::fetched_assets_present()) continue;
    ++scenes;
    const RenderScene scene = build_render_scene(parse_scene_file(entry.path()));
    const CrosscheckReport report = check_backends(scene, 20000, 1);
    EXPECT_TRUE(report.passed()) << entry.path() << "\n" << summary(report);
    EXPECT_GT(report.identical + report.within_tolerance, report.rays * 99 / 100) << entry.path();
  }
  EXPECT_GT(scenes, 0);
}

TEST(Crosscheck, CommandExitsZeroWhenTheBackendsAgree) {
  std::string output;
  const std::string scene = (test::scenes_dir() / "many_spheres.yaml").string();
  const std::string rtpro = test::rtpro_executable().string();
  const int code = test::run_command(rtpro + " crosscheck '" + scene + "' --rays 4000", &output);
  EXPECT_EQ(code, 0) << output;
  EXPECT_NE(output.find("mismatches         0"), std::string::npos) << output;
  EXPECT_NE(output.find("PASSED"), std::string::npos) << output;

  EXPECT_EQ(test::run_command(rtpro + " crosscheck /nonexistent.yaml", &output), 2) << output;
  EXPECT_EQ(test::run_command(rtpro + " crosscheck '" + scene + "' --rays 0", &output), 2) << output;
}

TEST(TracingFpMode, FlushesDenormalsToZero) {
  set_tracing_fp_mode();
  volatile float tiny = 1e-30f;
  volatile float scale = 1e-10f;
  const float product = tiny * scale;  // 1e-40 is denormal: flushed to zero
  EXPECT_EQ(std::bit_cast<std::uint32_t>(product), 0u);
}

}  // namespace crosscheck_test
}  // namespace rtpro
