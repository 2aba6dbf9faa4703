// Surface reconstruction four sphere or triangle hits at a time must be make_surface's, bit for
// bit, and its mirror directions the scalar reflect's.
#include "surface_batch.h"

#include "rtpro/backend/backend.h"
#include "test_fixtures.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace rtpro {
namespace surface_test {

std::uint32_t bits(float v) { return std::bit_cast<std::uint32_t>(v); }

void expect_same_vector(const Vec3& actual, const Vec3& expected, const char* what, int hit) {
  for (int axis = 0; axis < 3; ++axis)
    ASSERT_EQ(bits(actual[axis]), bits(expected[axis])) << what << " axis " << axis << " of hit " << hit;
}

// Every field of `actual` is `expected`'s, bit for bit.
void expect_same_surface(const SurfacePoint& actual, const SurfacePoint& expected, int hit) {
  expect_same_vector(actual.position, expected.position, "position", hit);
  expect_same_vector(actual.geometric_normal, expected.geometric_normal, "geometric normal", hit);
  expect_same_vector(actual.shading_normal, expected.shading_normal, "shading normal", hit);
  ASSERT_EQ(actual.front_face, expected.front_face) << hit;
  ASSERT_EQ(bits(actual.position_error), bits(expected.position_error)) << hit;
  ASSERT_EQ(actual.material, expected.material) << hit;
  ASSERT_EQ(actual.object_id, expected.object_id) << hit;
  ASSERT_EQ(bits(actual.tex_u), bits(expected.tex_u)) << hit;
  ASSERT_EQ(bits(actual.tex_v), bits(expected.tex_v)) << hit;
}

// Every field of four surfaces made at once against make_surface and reflect, one hit at a time.
template <typename MakeFour>
void expect_same_surfaces(const RenderScene& scene, const std::vector<Ray>& rays, const std::vector<Hit>& hits,
                          MakeFour make_four, int& back_faces) {
  for (std::size_t first = 0; first + 4 <= hits.size(); first += 4) {
    const Ray* ray_ptrs[4];
    const Hit* hit_ptrs[4];
    SurfacePoint four[4];
    SurfacePoint* out[4];
    Vec3 four_mirrors[4];
    Vec3* mirrors[4];
    for (int k = 0; k < 4; ++k) {
      ray_ptrs[k] = &rays[first + k];
      hit_ptrs[k] = &hits[first + k];
      out[k] = &four[k];
      mirrors[k] = &four_mirrors[k];
    }
    make_four(scene, ray_ptrs, hit_ptrs, out, mirrors);
    for (int k = 0; k < 4; ++k) {
      const int hit = static_cast<int>(first) + k;
      const SurfacePoint one = make_surface(scene, rays[first + k], hits[first + k]);
      ASSERT_NO_FATAL_FAILURE(expect_same_surface(four[k], one, hit));
      expect_same_vector(four_mirrors[k], reflect(normalize(rays[first + k].dir), one.shading_normal), "mirror", hit);
      back_faces += !one.front_face;
    }
  }
}

// Hits of random rays (from outside and inside spheres, at several scales) on the top-level
// spheres of a mixed scene, made four at a time and one at a time.
void expect_four_at_a_time_is_make_surface() {
  for (const float extent : {0.01f, 1.0f, 1000.0f}) {
    RenderScene scene = test::random_mixed_scene(7, 300, 100, 10);
    for (Geometry& g : scene.top.geometries)
      if (auto* set = std::get_if<SphereSet>(&g))
        for (Sphere& s : set->spheres) {
          s.center = s.center * extent;
          s.radius *= extent;
        }
    const auto backend = make_backend(BackendKind::kNative, scene, {});
    std::mt19937 rng(3);
    std::vector<Ray> rays;
    std::vector<Hit> hits;
    for (int i = 0; i < 40000 && hits.size() < 8000; ++i) {
      const Ray ray = test::random_ray(rng, extent * 4.0f);
      Hit hit;
      if (backend->intersect(ray, hit) && is_plain_sphere_hit(scene, hit)) {
        rays.push_back(ray);
        hits.push_back(hit);
      }
    }
    ASSERT_GT(hits.size(), 2000u) << "extent " << extent;
    int back_faces = 0;
    expect_same_surfaces(
        scene, rays, hits, [](auto&&... four) { make_sphere_surfaces4(four...); }, back_faces);
    EXPECT_GT(back_faces, 50) << "rays from inside spheres are exercised, extent " << extent;
  }
}

// Hit records on two top-level meshes, one flat and one smooth with per-triangle materials,
// degenerate triangles (no normal: the fallback to the ray) and vertex normals that are zero or
// face away, at several scales. The records are drawn, not traced: make_surface takes any
// barycentrics, so the edge cases come as often as wanted.
void expect_four_triangle_hits_at_a_time_are_make_surface() {
  for (const float extent : {0.01f, 1.0f, 1000.0f}) {
    std::mt19937 rng(5);
    RenderScene scene = test::empty_scene();
    TriangleMesh flat = test::random_triangles(rng, 200, 4.0f * extent);
    flat.material = 1;
    TriangleMesh smooth = test::random_triangles(rng, 200, 4.0f * extent);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (std::size_t i = 0; i < smooth.vertices.size(); ++i)
      smooth.normals.push_back(i % 7 == 0 ? Vec3() : Vec3{unit(rng), unit(rng), unit(rng)});
    for (std::size_t t = 0; t < smooth.triangles.size(); ++t) {
      smooth.triangle_materials.push_back(static_cast<std::uint32_t>(t % 2));
      if (t % 11 == 0) smooth.triangles[t].v1 = smooth.triangles[t].v0;  // no area, no normal
    }
    scene.top.geometries.emplace_back(std::move(flat));
    scene.top.geometries.emplace_back(std::move(smooth));
    std::vector<Ray> rays;
    std::vector<Hit> hits;
    int degenerate = 0;
    for (int i = 0; i < 8000; ++i) {
      Hit hit;
      hit.geom_id = static_cast<std::uint32_t>(rng() % 2);
      hit.prim_id = static_cast<std::uint32_t>(rng() % 200);
      hit.u = i % 13 == 0 ? 0.0f : std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
      hit.v = std::uniform_real_distribution<float>(0.0f, 1.0f - hit.u)(rng);
      hit.t = extent;
      ASSERT_TRUE(is_plain_triangle_hit(scene, hit));
      degenerate += hit.geom_id == 1 && hit.prim_id % 11 == 0;
      rays.push_back(test::random_ray(rng, extent * 4.0f));
      hits.push_back(hit);
    }
    int back_faces = 0;
    expect_same_surfaces(
        scene, rays, hits, [](auto&&... four) { make_triangle_surfaces4(four...); }, back_faces);
    EXPECT_GT(back_faces, 1000) << "extent " << extent;
    EXPECT_GT(degenerate, 100) << "extent " << extent;
  }
}

TEST(Surface, FourSphereHitsAtATimeAreMakeSurfaceBitForBit) { expect_four_at_a_time_is_make_surface(); }

TEST(Surface, FourTriangleHitsAtATimeAreMakeSurfaceBitForBit) {
  expect_four_triangle_hits_at_a_time_are_make_surface();
}

TEST(Surface, FourTriangleHitsAtATimeAreMakeSurfaceUnderTheTracingFloatingPointMode) {
  test::in_tracing_fp_mode(expect_four_triangle_hits_at_a_time_are_make_surface);
}

TEST(Surface, FourSphereHitsAtATimeAreMakeSurfaceUnderTheTracingFloatingPointMode) {
  test::in_tracing_fp_mode(expect_four_at_a_time_is_make_surface);
}

// Plain: a top-level primitive of kind `Kind` whose material has no image texture (instances and
// other kinds are not, and a textured one needs its texture coordinates from make_surface).
template <typename Kind, typename IsPlain>
void expect_plain_hits_are(int triangles, IsPlain is_plain) {
  RenderScene scene = test::random_mixed_scene(7, 50, triangles, 5);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  std::mt19937 rng(9);
  std::vector<Hit> hits;
  int plain = 0, other = 0;
  for (int i = 0; i < 20000; ++i) {
    Hit hit;
    if (!backend->intersect(test::random_ray(rng, 4.0f), hit)) continue;
    hits.push_back(hit);
    const bool top_level_kind =
        hit.inst_id == kInvalidId && std::holds_alternative<Kind>(scene.top.geometries[hit.geom_id]);
    EXPECT_EQ(is_plain(scene, hit), top_level_kind);
    (top_level_kind ? plain : other) += 1;
  }
  EXPECT_GT(plain, 100);
  EXPECT_GT(other, 100);
  for (Material& m : scene.materials) m.base_color = ImageTexture{0, Color(1.0f), TextureSampling{}};
  for (const Hit& hit : hits) EXPECT_FALSE(is_plain(scene, hit));
}

// make_surfaces over a traced batch mixing plain sphere and triangle hits, instanced and textured
// ones (one at a time) and misses (left alone): each surface make_surface's, bit for bit.
TEST(Surface, ABatchOfHitsIsMakeSurfaceOfEachHit) {
  RenderScene scene = test::random_mixed_scene(11, 200, 60, 12);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  std::mt19937 rng(13);
  std::vector<Ray> rays;
  std::vector<Hit> hits;
  for (int i = 0; i < 6000; ++i) {
    rays.push_back(test::random_ray(rng, 4.0f));
    Hit hit;
    if (!backend->intersect(rays.back(), hit)) hit = Hit{};
    hits.push_back(hit);
  }
  SurfacePoint untouched;
  untouched.material = 12345;
  std::vector<SurfacePoint> batch(hits.size(), untouched);
  make_surfaces(scene, true, rays, hits, batch);
  int plain_spheres = 0, plain_triangles = 0, misses = 0, others = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    const int hit = static_cast<int>(i);
    if (!hits[i].valid()) {
      ASSERT_EQ(batch[i].material, 12345u) << hit;
      ++misses;
      continue;
    }
    plain_spheres += is_plain_sphere_hit(scene, hits[i]);
    plain_triangles += is_plain_triangle_hit(scene, hits[i]);
    others += !is_plain_sphere_hit(scene, hits[i]) && !is_plain_triangle_hit(scene, hits[i]);
    const SurfacePoint one = make_surface(scene, rays[i], hits[i]);
    ASSERT_NO_FATAL_FAILURE(expect_same_surface(batch[i], one, hit));
  }
  EXPECT_GT(plain_spheres, 100);
  EXPECT_GT(plain_triangles, 100);
  EXPECT_GT(misses, 100);
  EXPECT_GT(others, 100) << "instanced hits, made one at a time";
}

TEST(Surface, OnlyTopLevelSpheresWithoutImageTexturesArePlain) {
  expect_plain_hits_are<SphereSet>(
      50, [](const RenderScene& scene, const Hit& hit) { return is_plain_sphere_hit(scene, hit); });
}

TEST(Surface, OnlyTopLevelTrianglesWithoutImageTexturesArePlain) {
  expect_plain_hits_are<TriangleMesh>(
      200, [](const RenderScene& scene, const Hit& hit) { return is_plain_triangle_hit(scene, hit); });
}

}  // namespace surface_test
}  // namespace rtpro
