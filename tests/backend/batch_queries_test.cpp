#include "rtpro/backend/backend.h"
#include "rtpro/core/fp_env.h"
#include "same_hit.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace rtpro {
namespace batch_queries_test {

// Which primitives the scene holds: with spheres alone (instances of spheres included) the Embree
// backend traces every batch in packets; with triangles in its top scene alone, scattered rays in
// packets; with instances of triangles, scattered rays one by one.
enum class SceneKind { kMixed, kSpheresOnly, kTopLevel };

// Batches must answer exactly what single rays answer, for every backend, coherence hint and
// scene kind: the renderer traces everything in batches, the references were made with single
// rays, and a ray's answer must not depend on which rays share its batch (tiles, threads, ranks).
class BatchQueries : public ::testing::TestWithParam<std::tuple<BackendKind, RayCoherence, SceneKind>> {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }

  static RenderScene scene(std::uint32_t seed) {
    switch (std::get<2>(GetParam())) {
      case SceneKind::kMixed: return test::random_mixed_scene(seed, 500, 500, 10);
      case SceneKind::kSpheresOnly: return test::random_mixed_scene(seed, 500, 0, 10);
      case SceneKind::kTopLevel: return test::random_mixed_scene(seed, 500, 500, 0);
    }
    throw std::logic_error("unknown scene kind");
  }
};

std::vector<Ray> test_rays() {
  std::mt19937 rng(11);
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    Ray ray = test::random_ray(rng, 6.0f);
    if (i % 3 == 1) ray.tfar = 2.0f;  // segments, like shadow rays to a point light
    rays.push_back(ray);
  }
  rays[17].org.x = std::numeric_limits<float>::quiet_NaN();  // untraceable: a miss, not a crash
  rays[18].dir = Vec3(0.0f);
  return rays;
}

// How many rays of a batch hit something, and how many are occluded.
struct BatchCounts {
  int hits = 0;
  int occluded = 0;
};

// A batch's hits and occlusion against the same rays traced alone, bit for bit; `times` holds
// each ray's time or is empty.
BatchCounts expect_batch_answers_as_single_rays(const Backend& backend, std::span<const Ray> rays,
                                                std::span<const float> times, RayCoherence coherence) {
  std::vector<Hit> hits(rays.size());
  backend.intersect(rays, times, hits, coherence);
  std::vector<std::uint8_t> occluded(rays.size(), 7);
  backend.occluded(rays, times, occluded, coherence);
  BatchCounts counts;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    const float time = times.empty() ? 0.0f : times[r];
    Hit single;
    if (!backend.intersect(rays[r], time, single)) single = Hit{};
    test::expect_same_hit(hits[r], single, r);
    EXPECT_EQ(occluded[r] == 1, backend.occluded(rays[r], time)) << r;
    counts.hits += single.valid();
    counts.occluded += occluded[r] == 1;
  }
  return counts;
}

// A batch's hits and occlusion whatever its grouping: the same answers when it is split in two at
// several places (another tile size groups a tile's rays otherwise), and, for hits, each ray as a
// batch of its own. Returns the whole batch's counts.
BatchCounts expect_batch_answers_whatever_its_grouping(const Backend& backend, std::span<const Ray> rays,
                                                       RayCoherence coherence) {
  std::vector<Hit> hits(rays.size());
  backend.intersect(rays, hits, coherence);
  std::vector<std::uint8_t> occluded(rays.size(), 7);
  backend.occluded(rays, occluded, coherence);
  for (std::size_t r = 0; r < rays.size(); ++r) {
    Hit alone;
    backend.intersect(rays.subspan(r, 1), std::span<Hit>(&alone, 1), coherence);
    test::expect_same_hit(hits[r], alone, r);
  }
  for (const std::size_t split : {1, 3, 5, 17}) {
    std::vector<Hit> regrouped(rays.size());
    const std::span<Hit> hits_out(regrouped);
    backend.intersect(rays.first(split), hits_out.first(split), coherence);
    backend.intersect(rays.subspan(split), hits_out.subspan(split), coherence);
    std::vector<std::uint8_t> occluded_regrouped(rays.size(), 7);
    const std::span<std::uint8_t> occluded_out(occluded_regrouped);
    backend.occluded(rays.first(split), occluded_out.first(split), coherence);
    backend.occluded(rays.subspan(split), occluded_out.subspan(split), coherence);
    for (std::size_t r = 0; r < rays.size(); ++r) {
      test::expect_same_hit(hits[r], regrouped[r], r);
      EXPECT_EQ(occluded[r], occluded_regrouped[r]) << r << " split at " << split;
    }
  }
  BatchCounts counts;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    counts.hits += hits[r].valid();
    counts.occluded += occluded[r] == 1;
  }
  return counts;
}

TEST_P(BatchQueries, IntersectMatchesSingleRays) {
  const auto [kind, coherence] = std::pair(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const RenderScene scene = BatchQueries::scene(7);
  const auto backend = make_backend(kind, scene, {});
  const std::vector<Ray> rays = test_rays();
  std::vector<Hit> hits(rays.size());
  backend->intersect(rays, hits, coherence);
  int found = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    Hit single;
    ASSERT_EQ(hits[i].valid(), backend->intersect(rays[i], single)) << i;
    if (!hits[i].valid()) continue;
    ++found;
    EXPECT_EQ(hits[i].t, single.t) << i;
    EXPECT_EQ(hits[i].u, single.u) << i;
    EXPECT_EQ(hits[i].v, single.v) << i;
    EXPECT_EQ(hits[i].inst_id, single.inst_id) << i;
    EXPECT_EQ(hits[i].geom_id, single.geom_id) << i;
    EXPECT_EQ(hits[i].prim_id, single.prim_id) << i;
  }
  EXPECT_GT(found, 300);
  EXPECT_LT(found, 2900);
}

TEST_P(BatchQueries, OccludedMatchesSingleRays) {
  const auto [kind, coherence] = std::pair(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const RenderScene scene = BatchQueries::scene(8);
  const auto backend = make_backend(kind, scene, {});
  const std::vector<Ray> rays = test_rays();
  std::vector<std::uint8_t> occluded(rays.size(), 7);
  backend->occluded(rays, occluded, coherence);
  int blocked = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    ASSERT_LE(occluded[i], 1) << i;
    ASSERT_EQ(occluded[i] == 1, backend->occluded(rays[i])) << i;
    blocked += occluded[i];
  }
  EXPECT_GT(blocked, 300);
  EXPECT_LT(blocked, 2900);
}

std::string suffix(SceneKind kind) {
  switch (kind) {
    case SceneKind::kMixed: return "_mixed";
    case SceneKind::kSpheresOnly: return "_spheres";
    case SceneKind::kTopLevel: return "_top_level";
  }
  throw std::logic_error("unknown scene kind");
}

INSTANTIATE_TEST_SUITE_P(Backends, BatchQueries,
                         ::testing::Combine(::testing::Values(BackendKind::kNative, BackendKind::kEmbree),
                                            ::testing::Values(RayCoherence::kCoherent, RayCoherence::kIncoherent),
                                            ::testing::Values(SceneKind::kMixed, SceneKind::kSpheresOnly,
                                                              SceneKind::kTopLevel)),
                         [](const auto& info) {
                           return std::string(backend_name(std::get<0>(info.param))) +
                                  (std::get<1>(info.param) == RayCoherence::kCoherent ? "_coherent" : "_incoherent") +
                                  suffix(std::get<2>(info.param));
                         });

// Where rays cross shared edges and vertices, several triangles meet them at exactly the same
// distance, and which one a traversal reports depends on the order it tests them in unless a tie
// rule decides (is_closer). A flat grid (eight triangles meet at every other vertex), and rays
// straight down through its vertices and edges' midpoints in groups of eight neighbours, along
// the diagonals, or converging on one vertex, so that Embree traces whole packets.
class BatchQueriesAtTies : public ::testing::Test {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }

  static constexpr int kCells = 24;

  // The grid placed by an instance, one unit up (rays and grid then meet at the same points); a
  // translation keeps the rays' coordinates exact in the instance's space.
  static RenderScene instanced_grid_scene() {
    RenderScene grid = grid_scene();
    RenderScene scene = test::empty_scene();
    Group prototype;
    prototype.geometries = std::move(grid.top.geometries);
    scene.prototypes.push_back(std::move(prototype));
    const Affine up = Affine::translate({0.0f, 1.0f, 0.0f});
    scene.top.geometries.emplace_back(Instance{0, up, *inverse(up)});
    return scene;
  }

  static std::vector<Ray> raised(std::vector<Ray> rays) {
    for (Ray& ray : rays) ray.org.y += 1.0f;
    return rays;
  }

  static RenderScene grid_scene() {
    RenderScene scene = test::empty_scene();
    TriangleMesh grid;
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i)
        grid.vertices.push_back({float(i) * 0.25f - 3.0f, 0.0f, float(j) * 0.25f - 3.0f});
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        const auto a = static_cast<std::uint32_t>(j * (kCells + 1) + i), b = a + 1, c = a + kCells + 1, d = c + 1;
        if ((i + j) % 2 == 0) {  // alternate diagonals
          grid.triangles.push_back({a, b, d});
          grid.triangles.push_back({a, d, c});
        } else {
          grid.triangles.push_back({a, b, c});
          grid.triangles.push_back({b, d, c});
        }
      }
    scene.top.geometries.emplace_back(std::move(grid));
    return scene;
  }

  static std::vector<Ray> tie_rays() {
    std::mt19937 rng(5);
    std::vector<Ray> rays;
    for (int group = 0; group < 600; ++group) {
      const int i0 = static_cast<int>(rng() % (kCells - 3)), j0 = static_cast<int>(rng() % (kCells - 3));
      const bool slanted = group % 3 == 2;     // along a diagonal, through an edge's midpoint
      const bool converging = group % 5 == 4;  // all eight through one vertex, from around it
      for (int k = 0; k < 8; ++k) {
        const int i = i0 + (converging ? 1 : static_cast<int>(rng() % 4));
        const int j = j0 + (converging ? 1 : static_cast<int>(rng() % 4));
        const float half = static_cast<float>(rng() % 3) * 0.125f;
        const Vec3 target{float(i) * 0.25f - 3.0f + half, 0.0f, float(j) * 0.25f - 3.0f};
        Ray ray;
        ray.org = slanted ? target + Vec3(1.0f, 2.0f, 1.0f) : target + Vec3(0.0f, 2.0f, 0.0f);
        ray.dir = slanted ? Vec3(-1.0f, -2.0f, -1.0f) : Vec3(0.0f, -1.0f, 0.0f);
        if (converging) {
          const Vec3 offset{float(k % 3) * 0.125f - 0.125f, 2.0f, float(k / 3) * 0.125f - 0.125f};
          ray.org = target + offset;
          ray.dir = -offset;
        }
        if (k % 4 == 3) ray.tfar = 1.0f;  // ending on the grid, where the distance is exact
        rays.push_back(ray);
      }
    }
    return rays;
  }

  // The batch's hits against single rays', bit for bit; the number of hits.
  static int expect_batches_hit_as_single_rays(const Backend& backend, RayCoherence coherence) {
    const std::vector<Ray> rays = tie_rays();
    std::vector<Hit> hits(rays.size());
    backend.intersect(rays, hits, coherence);
    int found = 0;
    for (std::size_t r = 0; r < rays.size(); ++r) {
      Hit single;
      backend.intersect(rays[r], single);
      test::expect_same_hit(hits[r], single, r);
      found += single.valid();
    }
    return found;
  }

  // The batch's occlusion against single rays'; the number of occluded rays.
  static int expect_batches_occluded_as_single_rays(const Backend& backend, RayCoherence coherence) {
    const std::vector<Ray> rays = tie_rays();
    std::vector<std::uint8_t> occluded(rays.size(), 7);
    backend.occluded(rays, occluded, coherence);
    int blocked = 0;
    for (std::size_t r = 0; r < rays.size(); ++r) {
      EXPECT_EQ(occluded[r] == 1, backend.occluded(rays[r]))
          << r << ": from (" << rays[r].org.x << ", " << rays[r].org.y << ", " << rays[r].org.z << ") along ("
          << rays[r].dir.x << ", " << rays[r].dir.y << ", " << rays[r].dir.z << ") to " << rays[r].tfar;
      blocked += occluded[r] == 1;
    }
    return blocked;
  }
};

TEST_F(BatchQueriesAtTies, NativeBatchesAnswerAsSingleRays) {
  const RenderScene scene = grid_scene();  // outlives the backend, which shares its arrays
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent}) {
    EXPECT_GT(expect_batches_hit_as_single_rays(*backend, coherence), 1800);
    EXPECT_GT(expect_batches_occluded_as_single_rays(*backend, coherence), 1800);
  }
}

TEST_F(BatchQueriesAtTies, EmbreeScatteredBatchesAnswerAsSingleRays) {
  const RenderScene scene = grid_scene();  // outlives the backend, which shares its arrays
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  EXPECT_GT(expect_batches_hit_as_single_rays(*backend, RayCoherence::kIncoherent), 1800);
  EXPECT_GT(expect_batches_occluded_as_single_rays(*backend, RayCoherence::kIncoherent), 1800);
}

// Embree's stream traversal, which traces coherent batches of a scene with triangles, reports
// another of the triangles at the same distance than its single rays do, depending on the rays
// it is grouped with (about 300 of these 4,800 rays, when the first three go alone), and misses
// hits exactly at tfar; the backend traces such hits again alone and asks the stream for one float
// further (embree_ray_batches.cpp, may_tie_with_a_neighbour).
TEST_F(BatchQueriesAtTies, EmbreeCoherentBatchesAnswerAsSingleRays) {
  const RenderScene scene = grid_scene();  // outlives the backend, which shares its arrays
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  EXPECT_GT(expect_batches_hit_as_single_rays(*backend, RayCoherence::kCoherent), 1800);
}

// The stream meets 7 of these rays, which run straight down exactly along the grid's outer edge
// (no neighbour on the other side), where they alone do not, and 2 to 5 of those change when
// regrouped: such candidates are refused and the rays traced again alone (refuse_edge_candidates).
// Robust or not: without robust traversal Embree picks kernels that skip filters unless the
// scene allows a context filter.
TEST_F(BatchQueriesAtTies, EmbreeCoherentOcclusionAsSingleRays) {
  const RenderScene scene = grid_scene();  // outlives the backend, which shares its arrays
  for (const bool robust : {true, false}) {
    BackendOptions options;
    options.embree_robust = robust;
    const auto backend = make_backend(BackendKind::kEmbree, scene, options);
    EXPECT_GT(expect_batches_occluded_as_single_rays(*backend, RayCoherence::kCoherent), 1800) << robust;
  }
}

// What the images rely on: a coherent batch's hits and shadows do not depend on how its rays are
// grouped (another tile size groups a tile's rays otherwise).
TEST_F(BatchQueriesAtTies, EmbreeCoherentBatchesAnswerWhateverTheirGrouping) {
  const RenderScene scene = grid_scene();  // outlives the backend, which shares its arrays
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  const BatchCounts counts = expect_batch_answers_whatever_its_grouping(*backend, tie_rays(), RayCoherence::kCoherent);
  EXPECT_GT(counts.hits, 1800);
  EXPECT_GT(counts.occluded, 1800);
}

// The grid deforming during the shutter (rising half a unit, level throughout, so the ties stay
// exact at every time): rays with times at ties, through Embree's motion kernels.
TEST_F(BatchQueriesAtTies, EmbreeTimedCoherentBatchesAnswerAsSingleRays) {
  RenderScene scene = grid_scene();
  auto& grid = std::get<TriangleMesh>(scene.top.geometries[0]);
  VertexArray raised_grid = grid.vertices;
  for (std::size_t i = 0; i < raised_grid.size(); ++i) {
    const Vec3 p = grid.vertices[i].position();
    raised_grid[i] = {p.x, p.y + 0.5f, p.z};
  }
  grid.vertex_steps = {grid.vertices, raised_grid};
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  // The tie rays (each traced again alone where it meets the grid near an edge), and as many
  // again through the cells' insides, which only the stream answers.
  std::vector<Ray> rays = tie_rays();
  for (std::size_t r = 0, ties = rays.size(); r < ties; ++r) {
    Ray inside = rays[r];
    inside.org = inside.org + Vec3(0.07f, 0.0f, 0.17f);
    rays.push_back(inside);
  }
  std::vector<float> times(rays.size());
  for (std::size_t r = 0; r < rays.size(); ++r) times[r] = static_cast<float>(r % 3) * 0.5f;
  for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent})
    EXPECT_GT(expect_batch_answers_as_single_rays(*backend, rays, times, coherence).hits, 3600);
}

// Curves: Embree answers a ray's curve hits in a stream or packet in their last bits otherwise
// than alone, but never otherwise for other company. Groups of eight rays from one point, aimed
// at points on and just beside random tubes and ribbons, so that many graze them; the curves
// alone (Embree traces them without robust mode) and beside a triangle (with it).
class BatchQueriesOnCurves : public ::testing::TestWithParam<std::tuple<CurveShape, bool>> {
 protected:
  void SetUp() override { set_tracing_fp_mode(); }

  static RenderScene curve_scene(CurveShape shape, bool beside_a_triangle) {
    std::mt19937 rng(3);
    RenderScene scene = test::empty_scene();
    CurveSet curves;
    curves.shape = shape;
    curves.basis = CurveBasis::kCatmullRom;
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), radius(0.01f, 0.05f);
    for (int c = 0; c < 300; ++c) {
      const Vec3 start{3.0f * unit(rng), 3.0f * unit(rng), 3.0f * unit(rng)};
      const Vec3 step{0.3f * unit(rng), 0.3f * unit(rng), 0.3f * unit(rng)};
      curves.segments.push_back(static_cast<std::uint32_t>(curves.points.size()));
      for (int k = 0; k < 4; ++k) curves.points.push_back({start + step * float(k), radius(rng)});
    }
    scene.top.geometries.emplace_back(std::move(curves));
    if (beside_a_triangle) {
      TriangleMesh mesh;
      mesh.vertices = {{-9, -9, -9}, {-8, -9, -9}, {-9, -8, -9}};
      mesh.triangles = {{0, 1, 2}};
      scene.top.geometries.emplace_back(std::move(mesh));
    }
    return scene;
  }

  static std::vector<Ray> grazing_rays(const RenderScene& scene) {
    const CurveSet& curves = std::get<CurveSet>(scene.top.geometries[0]);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<Ray> rays;
    for (int group = 0; group < 500; ++group) {
      const Vec3 eye{6.0f * unit(rng), 6.0f * unit(rng), 8.0f};
      for (int k = 0; k < 8; ++k) {
        const CurvePoint& p = curves.points[(rng() % curves.segments.size()) * 4 + 1 + rng() % 2];
        const Vec3 side = normalize(Vec3{unit(rng), unit(rng), unit(rng)});
        const float reach = p.radius * (k % 2 == 0 ? 1.0f + 1e-4f * unit(rng) : 0.5f * (1.0f + unit(rng)));
        Ray ray;
        ray.org = eye;
        ray.dir = p.position + side * reach - eye;
        if (k % 4 == 3) ray.tfar = 1.0f;
        rays.push_back(ray);
      }
    }
    return rays;
  }
};

TEST_P(BatchQueriesOnCurves, EmbreeBatchesAnswerWhateverTheirGrouping) {
  const RenderScene scene = curve_scene(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  const std::vector<Ray> rays = grazing_rays(scene);
  for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent}) {
    const BatchCounts counts = expect_batch_answers_whatever_its_grouping(*backend, rays, coherence);
    EXPECT_GT(counts.hits, 1000);
    EXPECT_GT(counts.occluded, 1000);
  }
}

// The native backend's packets answer each curve lane as the ray alone.
TEST_P(BatchQueriesOnCurves, NativeBatchesAnswerAsSingleRays) {
  const RenderScene scene = curve_scene(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const std::vector<Ray> rays = grazing_rays(scene);
  for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent})
    EXPECT_GT(expect_batch_answers_as_single_rays(*backend, rays, {}, coherence).hits, 1000);
}

INSTANTIATE_TEST_SUITE_P(Shapes, BatchQueriesOnCurves,
                         ::testing::Combine(::testing::Values(CurveShape::kRound, CurveShape::kFlat),
                                            ::testing::Bool()),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == CurveShape::kRound ? "round" : "flat") +
                                  (std::get<1>(info.param) ? "_beside_a_triangle" : "_alone");
                         });

TEST_F(BatchQueriesAtTies, EmbreeCoherentBatchesThroughAnInstanceWhateverTheirGrouping) {
  const RenderScene scene = instanced_grid_scene();
  const auto backend = make_backend(BackendKind::kEmbree, scene, {});
  const std::vector<Ray> rays = raised(tie_rays());
  for (const RayCoherence coherence : {RayCoherence::kCoherent, RayCoherence::kIncoherent}) {
    EXPECT_GT(expect_batch_answers_as_single_rays(*backend, rays, {}, coherence).hits, 1800);
    expect_batch_answers_whatever_its_grouping(*backend, rays, coherence);
  }
}

}  // namespace batch_queries_test
}  // namespace rtpro
