// A leaf's triangles tested four at a time must answer what intersect_triangle answers one at a
// time, bit for bit: images must not depend on whether a leaf is tested so, nor on whether the
// CPU has the AVX2 the four-wide test needs.
#include "triangle_leaves.h"

#include "native_traversal.h"
#include "sphere_lanes.h"
#include "test_scenes.h"
#include "rtpro/backend/hit.h"
#include "rtpro/geometry/triangle_intersect.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace rtpro {
namespace triangle_leaves_test {

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

struct Triangle {
  Vec3 p[3];
};

Vec3 grid_point(std::mt19937& rng) {
  std::uniform_int_distribution<int> coordinate(-3, 3);
  return {float(coordinate(rng)), float(coordinate(rng)), float(coordinate(rng))};
}

// Triangles of every shape the scenes hold and a few they should not: ordinary, slivers, a
// repeated vertex, all three on one point, huge and tiny coordinates, and on an integer grid,
// where rays through vertices and edges give barycentrics of exactly 0 and 1.
Triangle random_triangle(std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 9);
  Triangle tri{
      {{unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)}, {unit(rng), unit(rng), unit(rng)}}};
  switch (kind(rng)) {
    case 8:
    case 9:
      for (Vec3& p : tri.p) p = grid_point(rng);
      break;
    case 0: tri.p[2] = tri.p[0] + (tri.p[1] - tri.p[0]) * 0.5f; break;  // collinear
    case 1: tri.p[1] = tri.p[0]; break;
    case 2: tri.p[1] = tri.p[2] = tri.p[0]; break;
    case 3:
      for (Vec3& p : tri.p) p = p * 1e7f;
      break;
    case 4:
      for (Vec3& p : tri.p) p = p * 1e-6f;
      break;
    default: break;
  }
  return tri;
}

// Rays aimed at the triangle's vertices and edges (where rounding decides), through its interior,
// lying in its plane, starting on it, short segments, zero and NaN directions.
Ray random_ray_at(std::mt19937& rng, const Triangle& tri) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f), positive(0.0f, 1.0f);
  std::uniform_int_distribution<int> kind(0, 11), vertex(0, 2);
  Ray ray{{unit(rng) * 3.0f, unit(rng) * 3.0f, unit(rng) * 3.0f}, 0.0f, {}, std::numeric_limits<float>::infinity()};
  const float a = positive(rng), b = positive(rng) * (1.0f - a);
  Vec3 target = tri.p[0] * (1.0f - a - b) + tri.p[1] * a + tri.p[2] * b;
  switch (kind(rng)) {
    case 10:
    case 11: {  // from a grid point exactly through a vertex or an edge's midpoint
      ray.org = grid_point(rng) * 2.0f + Vec3(0.0f, 0.0f, 9.0f);
      const int i = vertex(rng);
      target = kind(rng) % 2 ? tri.p[i] : (tri.p[i] + tri.p[(i + 1) % 3]) * 0.5f;
      ray.dir = target - ray.org;
      return ray;
    }
    case 0: target = tri.p[vertex(rng)]; break;
    case 1: target = tri.p[0] + (tri.p[1] - tri.p[0]) * positive(rng); break;
    case 2: target = tri.p[1] + (tri.p[2] - tri.p[1]) * positive(rng); break;
    case 3: {
      const float u = unit(rng), v = unit(rng);
      ray.org = tri.p[0] + (tri.p[1] - tri.p[0]) * u + (tri.p[2] - tri.p[0]) * v;
      break;
    }
    case 4: ray.org = target; break;
    case 5: ray.tfar = positive(rng) * 4.0f; break;
    case 6: ray.tnear = -positive(rng); break;
    case 7: ray.dir = {0.0f, 0.0f, 0.0f}; return ray;
    case 8: ray.dir = {std::numeric_limits<float>::quiet_NaN(), 1.0f, 0.0f}; return ray;
    default: break;
  }
  ray.dir = target - ray.org + Vec3{unit(rng), unit(rng), unit(rng)} * 1e-4f;
  return ray;
}

// Four triangles as the rows of a TriangleLeaves hold them, with `gap` unrelated columns
// between the rows.
struct Rows {
  std::size_t stride;
  std::vector<float> values;
};

Rows rows_of(const std::vector<Triangle>& tris, std::size_t gap = 5) {
  Rows rows{kBlockWidth + gap, {}};
  rows.values.assign(9 * rows.stride, std::numeric_limits<float>::quiet_NaN());
  for (unsigned j = 0; j < kBlockWidth; ++j)
    for (int vertex = 0; vertex < 3; ++vertex)
      for (int c = 0; c < 3; ++c)
        rows.values[(3 * vertex + c) * rows.stride + j] = j < tris.size() ? tris[j].p[vertex][c] : 0.0f;
  return rows;
}

[[gnu::target("avx2")]] unsigned test_block(const Rows& rows, unsigned slots, const Ray& ray, float tfar,
                                            BlockHits& hits) {
  return intersect_block(load_block(rows.values.data(), rows.stride), slots, block_ray(ray.org, ray.dir, ray.tnear),
                         tfar, hits);
}

TEST(TriangleLeaves, EverySlotAnswersWhatTheScalarTestAnswersBitForBit) {
  if (!sphere_lanes_vectorised()) GTEST_SKIP() << "the CPU has no AVX2";
  std::mt19937 rng(26);
  int hits_seen = 0;
  for (int round = 0; round < 20000; ++round) {
    std::vector<Triangle> tris;
    for (int j = 0; j < 4; ++j) tris.push_back(random_triangle(rng));
    const Ray ray = random_ray_at(rng, tris[round % 4]);
    BlockHits hits;
    const unsigned mask = test_block(rows_of(tris), 0xFu, ray, ray.tfar, hits);
    for (unsigned j = 0; j < 4; ++j) {
      TriangleHit expected;
      const bool hit =
          intersect_triangle(tris[j].p[0], tris[j].p[1], tris[j].p[2], ray.org, ray.dir, ray.tnear, ray.tfar, expected);
      ASSERT_EQ(hit, ((mask >> j) & 1u) != 0) << "round " << round << " slot " << j;
      if (!hit) continue;
      ++hits_seen;
      EXPECT_TRUE(same_bits(expected.t, hits.t[j]) && same_bits(expected.u, hits.u[j]) &&
                  same_bits(expected.v, hits.v[j]))
          << "round " << round << " slot " << j;
    }
  }
  EXPECT_GT(hits_seen, 5000);  // the rays were aimed: most rounds hit something
}

TEST(TriangleLeaves, SlotsOutsideTheLeafAreNeverHit) {
  if (!sphere_lanes_vectorised()) GTEST_SKIP() << "the CPU has no AVX2";
  // Four copies of one triangle, of which the leaf owns the first one, two or three.
  const Triangle tri{{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}};
  const Rows rows = rows_of({tri, tri, tri, tri});
  const Ray ray{{0.0f, -0.5f, -1.0f}, 0.0f, {0.0f, 0.0f, 1.0f}, std::numeric_limits<float>::infinity()};
  for (unsigned slots : {0x1u, 0x3u, 0x7u, 0xFu}) {
    BlockHits hits;
    EXPECT_EQ(test_block(rows, slots, ray, ray.tfar, hits), slots);
  }
  // Zero columns (the padding past the last reference, and references that are not triangles)
  // are degenerate: never hit, even by a ray through the origin where their vertices sit.
  const Rows padded = rows_of({tri});
  for (const Vec3 org : {Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, -0.5f, -1.0f)}) {
    BlockHits hits;
    const Ray through{org, 0.0f, {0.0f, 0.0f, 1.0f}, std::numeric_limits<float>::infinity()};
    EXPECT_EQ(test_block(padded, 0xFu, through, through.tfar, hits), 1u);
  }
}

// A scene of triangles only (every top-level leaf a triangle leaf), one of spheres and triangles
// mixed (triangle leaves beside others), and instances of both kinds of prototype.
std::vector<RenderScene> scenes() {
  std::vector<RenderScene> out;
  std::mt19937 rng(7);
  RenderScene triangles = test::empty_scene();
  triangles.top.geometries.push_back(test::random_triangles(rng, 3000, 4.0f));
  out.push_back(std::move(triangles));
  out.push_back(test::random_mixed_scene(3, 200, 2000, 6));
  out.push_back(test::random_mixed_scene(4, 0, 1500, 0));
  return out;
}

TEST(TriangleLeaves, TraversalAnswersTheSameWithAndWithoutRows) {
  if (!sphere_lanes_vectorised()) GTEST_SKIP() << "the CPU has no AVX2";
  std::mt19937 rng(11);
  for (const RenderScene& scene : scenes()) {
    const NativeTraversal with(scene, true), without(scene, false);
    EXPECT_GT(with.memory_bytes(), without.memory_bytes());
    int hits_seen = 0;
    for (int batch = 0; batch < 400; ++batch) {
      std::vector<Ray> rays;
      for (unsigned k = 0; k < kPacketSize; ++k) {
        Ray ray = test::random_ray(rng, 5.0f);
        if (k % 3 == 0) ray.tfar = 2.0f;
        rays.push_back(ray);
      }
      RayPacket packet_with, packet_without;
      for (unsigned k = 0; k < kPacketSize; ++k) {
        packet_with.set(k, rays[k], rays[k].tfar);
        packet_without.set(k, rays[k], rays[k].tfar);
      }
      packet_with.finish(kPacketSize);
      packet_without.finish(kPacketSize);
      Hit best_with[kPacketSize], best_without[kPacketSize];
      with.closest_in_packet(packet_with, false, 0xFFu, best_with);
      without.closest_in_packet(packet_without, false, 0xFFu, best_without);
      EXPECT_EQ(with.any_in_packet(packet_with, false, 0xFFu), without.any_in_packet(packet_without, false, 0xFFu));
      for (unsigned k = 0; k < kPacketSize; ++k) {
        Hit single_with, single_without;
        float t_with = rays[k].tfar, t_without = rays[k].tfar;
        with.closest(rays[k], 0.0f, single_with, t_with);
        without.closest(rays[k], 0.0f, single_without, t_without);
        ASSERT_EQ(std::memcmp(&single_with, &single_without, sizeof(Hit)), 0) << "batch " << batch << " ray " << k;
        ASSERT_TRUE(same_bits(t_with, t_without));
        ASSERT_EQ(std::memcmp(&best_with[k], &single_with, sizeof(Hit)), 0) << "batch " << batch << " lane " << k;
        ASSERT_EQ(std::memcmp(&best_without[k], &single_with, sizeof(Hit)), 0);
        ASSERT_TRUE(same_bits(packet_with.tmax[k], t_with) && same_bits(packet_without.tmax[k], t_with));
        EXPECT_EQ(with.any(rays[k], 0.0f), without.any(rays[k], 0.0f));
        hits_seen += single_with.valid();
      }
    }
    EXPECT_GT(hits_seen, 300);
  }
}

TEST(TriangleLeaves, RowsHoldEveryReferencesVerticesAndMarkTriangleLeaves) {
  const RenderScene scene = test::random_mixed_scene(5, 300, 3000, 0);
  const Bvh bvh = build_bvh(scene.top, scene.prototype_bounds());
  const TriangleLeaves leaves = build_triangle_leaves(scene.top, bvh);
  ASSERT_EQ(leaves.triangle_leaf.size(), bvh.nodes.size());
  ASSERT_EQ(leaves.stride, bvh.refs.size() + kBlockWidth - 1);
  for (std::size_t r = 0; r < leaves.stride; ++r) {
    Vec3 p[3] = {};
    if (r < bvh.refs.size()) {
      if (const auto* mesh = std::get_if<TriangleMesh>(&scene.top.geometries[bvh.refs[r].geom])) {
        const TriangleIndices& tri = mesh->triangles[bvh.refs[r].prim];
        p[0] = mesh->vertex(tri.v0);
        p[1] = mesh->vertex(tri.v1);
        p[2] = mesh->vertex(tri.v2);
      }
    }
    for (int vertex = 0; vertex < 3; ++vertex)
      for (int c = 0; c < 3; ++c)
        ASSERT_TRUE(
            same_bits(leaves.column(static_cast<std::uint32_t>(r))[(3 * vertex + c) * leaves.stride], p[vertex][c]))
            << "reference " << r << " vertex " << vertex;
  }
  int marked = 0, unmarked = 0;
  for (std::size_t n = 0; n < bvh.nodes.size(); ++n) {
    const BvhNode& node = bvh.nodes[n];
    bool triangles_only = node.is_leaf();
    for (std::uint32_t i = 0; node.is_leaf() && i < node.count; ++i)
      triangles_only &= kind_of(scene.top.geometries[bvh.refs[node.index + i].geom]) == GeometryKind::kTriangles;
    EXPECT_EQ(leaves.triangle_leaf[n] != 0, triangles_only) << "node " << n;
    marked += triangles_only;
    unmarked += node.is_leaf() && !triangles_only;
  }
  EXPECT_GT(marked, 10);
  EXPECT_GT(unmarked, 10);
  // Spheres alone: no triangle leaf, no rows.
  RenderScene spheres = test::empty_scene();
  std::mt19937 rng(2);
  spheres.top.geometries.push_back(test::random_spheres(rng, 500, 3.0f));
  const Bvh sphere_bvh = build_bvh(spheres.top, spheres.prototype_bounds());
  const TriangleLeaves sphere_leaves = build_triangle_leaves(spheres.top, sphere_bvh);
  EXPECT_TRUE(sphere_leaves.vertices.empty());
  EXPECT_EQ(sphere_leaves.triangle_leaf.size(), sphere_bvh.nodes.size());
  EXPECT_EQ(std::count(sphere_leaves.triangle_leaf.begin(), sphere_leaves.triangle_leaf.end(), 1), 0);
  const TriangleLeaves disabled = build_triangle_leaves(scene.top, bvh, false);
  EXPECT_TRUE(disabled.vertices.empty());
  EXPECT_EQ(std::count(disabled.triangle_leaf.begin(), disabled.triangle_leaf.end(), 1), 0);
}

}  // namespace triangle_leaves_test
}  // namespace rtpro
