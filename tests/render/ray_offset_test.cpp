// Spawned rays must never re-hit the surface they leave ("shadow acne"), at any scene scale and
// distance from the origin, for spheres, triangles and instances alike.
#include "ray_offset.h"

#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "surface.h"
#include "test_fixtures.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <xmmintrin.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <random>

namespace rtpro {
namespace ray_offset_test {

struct ScaleCase {
  float extent;
  float offset;  // distance of the whole scene from the world origin
};

RenderScene scene_at_scale(const ScaleCase& c, std::uint32_t seed) {
  RenderScene scene = test::random_mixed_scene(seed, 200, 200, 20);
  const Affine placement = compose(Affine::translate(Vec3(c.offset)), Affine::scale(Vec3(c.extent / 4.0f)));
  // Re-home every top-level geometry by wrapping the whole scene in one placement.
  for (Geometry& g : scene.top.geometries) {
    if (auto* set = std::get_if<SphereSet>(&g)) {
      for (Sphere& s : set->spheres) {
        s.center = placement.apply_point(s.center);
        s.radius *= c.extent / 4.0f;
      }
    } else if (auto* mesh = std::get_if<TriangleMesh>(&g)) {
      for (MeshVertex& v : mesh->vertices) {
        const Vec3 p = placement.apply_point(v.position());
        v = {p.x, p.y, p.z};
      }
    } else if (auto* instance = std::get_if<Instance>(&g)) {
      instance->object_to_world = compose(placement, instance->object_to_world);
      instance->world_to_object = *inverse(instance->object_to_world);
    }
  }
  return scene;
}

// Whether `org` lies outside the sphere the hit refers to (re-hits from inside are legitimate).
bool started_outside_hit_sphere(const RenderScene& scene, const Ray& ray, const Hit& hit) {
  const Group& group = hit.inst_id == kInvalidId
                           ? scene.top
                           : scene.prototypes[std::get<Instance>(scene.top.geometries[hit.inst_id]).prototype];
  const auto* set = std::get_if<SphereSet>(&group.geometries[hit.geom_id]);
  if (!set) return true;
  Vec3 org = ray.org;
  if (hit.inst_id != kInvalidId)
    org = std::get<Instance>(scene.top.geometries[hit.inst_id]).world_to_object.apply_point(org);
  const Sphere& s = set->spheres[hit.prim_id];
  return length(org - s.center) > s.radius * 1.001f;
}

bool same_primitive(const Hit& a, const Hit& b) {
  return a.inst_id == b.inst_id && a.geom_id == b.geom_id && a.prim_id == b.prim_id;
}

class RayOffsetTest : public ::testing::TestWithParam<ScaleCase> {};

TEST_P(RayOffsetTest, SpawnedRaysNeverReHitTheirOwnSurface) {
  const ScaleCase c = GetParam();
  const RenderScene scene = scene_at_scale(c, 11);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int surfaces = 0, spawned = 0;
  for (int i = 0; i < 4000; ++i) {
    Ray ray = test::random_ray(rng, c.extent);
    ray.org = ray.org + Vec3(c.offset);
    Hit hit;
    if (!backend->intersect(ray, hit) || !started_outside_hit_sphere(scene, ray, hit)) continue;
    ++surfaces;
    const SurfacePoint sp = make_surface(scene, ray, hit);
    for (int k = 0; k < 8; ++k) {
      Vec3 d{unit(rng), unit(rng), unit(rng)};
      if (length(d) < 1e-3f) continue;
      d = normalize(d);
      if (dot(d, sp.geometric_normal) < 0.0f) d = -d;
      Hit again;
      ++spawned;
      const Ray leaving = spawn_ray(sp, d);
      ASSERT_FALSE(backend->intersect(leaving, again) && same_primitive(again, hit))
          << "re-hit at t=" << again.t << " scale " << c.extent << " offset " << c.offset;
      // Shadow rays towards a point up to 100 extents away must not be blocked by the surface.
      const Vec3 target = sp.position + d * (c.extent * 100.0f * (0.5f + 0.5f * unit(rng)));
      const Ray to_light = spawn_ray_to(sp, target);
      if (backend->intersect(to_light, again)) {
        ASSERT_FALSE(same_primitive(again, hit));
      }
    }
  }
  EXPECT_GT(surfaces, 500);
  EXPECT_GT(spawned, 4000);
}

INSTANTIATE_TEST_SUITE_P(Scales, RayOffsetTest,
                         ::testing::Values(ScaleCase{1.0f, 0.0f}, ScaleCase{0.01f, 0.0f}, ScaleCase{1000.0f, 0.0f},
                                           ScaleCase{1.0f, 10000.0f}, ScaleCase{50.0f, -2.0e5f}));

TEST(RayOffset, OriginMovesToTheSideTheRayLeavesFrom) {
  SurfacePoint sp{};
  sp.position = {0, 0, 0};
  sp.geometric_normal = {0, 0, 1};
  sp.shading_normal = {0, 0, 1};
  sp.position_error = 1e-4f;
  EXPECT_GT(offset_ray_origin(sp, {0, 0, 1}).z, 0.0f);
  EXPECT_LT(offset_ray_origin(sp, {0, 0, -1}).z, 0.0f);
}

}  // namespace ray_offset_test
}  // namespace rtpro

namespace rtpro {
namespace ray_offset_test {

// The whole check, run in the default floating-point mode and in the one tracing threads use.
void expect_rounding_away_from_the_surface() {
  SurfacePoint sp{};
  sp.geometric_normal = {1, 0, 0};
  sp.shading_normal = {1, 0, 0};
  sp.position_error = 1e-38f;  // far below one ulp of x: only the rounding step moves the origin
  for (float x : {1.0f, -1.0f, 1e-30f, -3.5e7f}) {
    sp.position = {x, 2.0f, -2.0f};
    const Vec3 out = offset_ray_origin(sp, {1, 0, 0});
    const Vec3 in = offset_ray_origin(sp, {-1, 0, 0});
    EXPECT_EQ(out.x, std::nextafter(x, 1e38f)) << x;
    EXPECT_EQ(in.x, std::nextafter(x, -1e38f)) << x;
    EXPECT_EQ(out.y, 2.0f);
  }
  sp.position = {0.0f, 0.0f, 0.0f};
  EXPECT_GT(offset_ray_origin(sp, {1, 0, 0}).x, 0.0f);
  EXPECT_LT(offset_ray_origin(sp, {-1, 0, 0}).x, 0.0f);
}

TEST(RayOffset, RoundsAwayFromTheSurfaceIncludingAtZero) { expect_rounding_away_from_the_surface(); }

// Tracing threads flush denormals to zero (core/fp_env.h): an error bound of 1e-38 is then zero
// and a step from 0 onto a denormal would be no step. A test earlier in the same process that
// rendered on this thread used to leave that mode behind and make the test above fail.
TEST(RayOffset, RoundsAwayFromTheSurfaceUnderTheTracingFloatingPointMode) {
  test::in_tracing_fp_mode(expect_rounding_away_from_the_surface);
}

// The SSE offset against its per-axis definition, bit for bit, over random points, normals and
// error bounds with the values where the rounding step branches: zeros of both signs, denormals,
// the smallest normal float, coordinates whose step crosses a power of two, axis-aligned normals.
void expect_sse_offset_equals_per_axis_definition() {
  std::mt19937 rng(17);
  const float specials[] = {0.0f,
                            -0.0f,
                            1e-40f,
                            -1e-40f,
                            std::numeric_limits<float>::min(),
                            -std::numeric_limits<float>::min(),
                            1.0f,
                            -1.0f,
                            2.0f,
                            0x1.fffffep0f,
                            -3.5e7f,
                            1e30f};
  std::uniform_int_distribution<int> pick(0, 2 * static_cast<int>(std::size(specials)));
  std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f);
  auto value = [&] {
    const int k = pick(rng);
    return k < static_cast<int>(std::size(specials)) ? specials[k] : coordinate(rng);
  };
  int moved = 0;
  for (int i = 0; i < 200000; ++i) {
    SurfacePoint sp{};
    sp.position = {value(), value(), value()};
    Vec3 n{value(), value(), value()};
    if (i % 3 == 0) n = Vec3(0.0f);
    n[i % 3] = i % 2 ? 1.0f : -1.0f;
    sp.geometric_normal = n;
    sp.position_error = i % 5 == 0 ? 1e-38f : std::fabs(coordinate(rng)) * 1e-6f;
    const Vec3 direction{value(), value(), value()};
    const Vec3 expected = offset_ray_origin_per_axis(sp, direction);
    const Vec3 actual = offset_ray_origin(sp, direction);
    for (int axis = 0; axis < 3; ++axis)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(actual[axis]), std::bit_cast<std::uint32_t>(expected[axis]))
          << "case " << i << " axis " << axis << ": " << actual[axis] << " vs " << expected[axis];
    moved += !(expected == sp.position);
  }
  EXPECT_GT(moved, 190000);
}

TEST(RayOffset, SseOffsetIsThePerAxisDefinitionBitForBit) { expect_sse_offset_equals_per_axis_definition(); }

TEST(RayOffset, SseOffsetIsThePerAxisDefinitionUnderTheTracingFloatingPointMode) {
  test::in_tracing_fp_mode(expect_sse_offset_equals_per_axis_definition);
}

// A vertex's shadow ray and next ray share its cached origins: each must be the origin that
// spawning on its own gives, whichever side asks first and however often.
TEST(RayOffset, SpawnOriginsAreTheOffsetOriginsOfEachSide) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
  for (int i = 0; i < 20000; ++i) {
    SurfacePoint sp{};
    sp.position = {coordinate(rng), coordinate(rng), coordinate(rng)};
    sp.geometric_normal = normalize(Vec3{coordinate(rng), coordinate(rng), coordinate(rng)});
    sp.position_error = std::fabs(coordinate(rng)) * 1e-6f;
    SpawnOrigins origins(sp);
    for (int k = 0; k < 4; ++k) {
      const Vec3 direction{coordinate(rng), coordinate(rng), coordinate(rng)};
      const Ray expected = spawn_ray(sp, direction);
      const Ray actual = spawn_ray(origins, direction);
      const Vec3 target = sp.position + direction;
      const Ray expected_to = spawn_ray_to(sp, target);
      const Ray actual_to = spawn_ray_to(origins, target);
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(actual.org[axis]), std::bit_cast<std::uint32_t>(expected.org[axis]));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(actual_to.org[axis]),
                  std::bit_cast<std::uint32_t>(expected_to.org[axis]));
        ASSERT_EQ(std::bit_cast<std::uint32_t>(actual_to.dir[axis]),
                  std::bit_cast<std::uint32_t>(expected_to.dir[axis]));
      }
      ASSERT_EQ(actual_to.tfar, expected_to.tfar);
    }
  }
}

}  // namespace ray_offset_test
}  // namespace rtpro
