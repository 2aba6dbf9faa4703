#include "rtpro/render/renderer.h"

#include "rtpro/backend/backend.h"
#include "rtpro/core/error.h"
#include "test_scenes.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cstring>
#include <limits>

namespace rtpro {
namespace renderer_test {

RenderScene test_scene() {
  RenderScene scene = test::random_mixed_scene(21, 300, 300, 10);
  test::set_camera(scene, 48, 32);
  scene.render.spp = 4;
  return scene;
}

RenderResult render_with(const RenderScene& scene, int threads, int tile_size, std::vector<Aov> aovs = {}) {
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, threads);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  RenderOptions options;
  options.tile_size = tile_size;
  options.aovs = std::move(aovs);
  return render_image(scene, *backend, options);
}

bool bit_identical(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}

TEST(TileSources, CountWhatIsLeftAsTheyHandTilesOut) {
  AllTilesSource all(3);
  TileListSource listed({7, 2});
  EXPECT_EQ(all.remaining(), 3u);
  EXPECT_EQ(listed.remaining(), 2u);
  all.next();
  listed.next();
  EXPECT_EQ(all.remaining(), 2u);
  EXPECT_EQ(listed.remaining(), 1u);
  while (all.next()) {
  }
  while (listed.next()) {
  }
  // Asking past the end must not wrap the count.
  all.next();
  listed.next();
  EXPECT_EQ(all.remaining(), 0u);
  EXPECT_EQ(listed.remaining(), 0u);
}

TEST(Renderer, ImageIsIndependentOfThreadsAndTiles) {
  const RenderScene scene = test_scene();
  const RenderResult one = render_with(scene, 1, 32);
  const RenderResult two = render_with(scene, 2, 32);
  const RenderResult odd_tiles = render_with(scene, 2, 7);
  const RenderResult one_tile = render_with(scene, 2, std::numeric_limits<int>::max());
  EXPECT_TRUE(bit_identical(one.image, two.image));
  EXPECT_TRUE(bit_identical(one.image, odd_tiles.image));
  EXPECT_TRUE(bit_identical(one.image, one_tile.image));
  EXPECT_EQ(one_tile.tiles_total, 1u);
  EXPECT_EQ(one.rays.total(), two.rays.total());
  EXPECT_EQ(one.rays[RayKind::kCamera], 48u * 32u * 4u);
  EXPECT_GT(one.rays[RayKind::kShadow], 0u);
  EXPECT_GT(one.rays[RayKind::kReflection], 0u);
  EXPECT_TRUE(one.complete());
}

TEST(Renderer, ImageIsNotBlankAndSeedChangesTheNoise) {
  RenderScene scene = test_scene();
  const RenderResult a = render_with(scene, 2, 16);
  scene.render.seed = 99;
  const RenderResult b = render_with(scene, 2, 16);
  float sum = 0.0f;
  for (float v : a.image.data) sum += v;
  EXPECT_GT(sum, 1.0f);
  EXPECT_FALSE(bit_identical(a.image, b.image));
}

TEST(Renderer, RegionPixelsEqualTheFullRender) {
  const RenderScene scene = test_scene();
  const RenderResult full = render_with(scene, 2, 16);
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  RenderOptions options;
  options.region = PixelRegion{5, 3, 29, 20};
  const RenderResult part = render_image(scene, *backend, options);
  for (int y = 0; y < scene.camera.height; ++y)
    for (int x = 0; x < scene.camera.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const bool inside = x >= 5 && x < 29 && y >= 3 && y < 20;
        ASSERT_EQ(part.image.at(x, y, c), inside ? full.image.at(x, y, c) : 0.0f) << x << "," << y;
      }
  options.region = PixelRegion{0, 0, 49, 10};
  EXPECT_THROW(render_image(scene, *backend, options), InputError);
}

// Cancels the render once three work items are done.
struct CancelAfterThreeTiles final : RenderObserver {
  std::atomic<bool>& cancel;
  explicit CancelAfterThreeTiles(std::atomic<bool>& flag) : cancel(flag) {}
  void tile_done(std::size_t done, std::size_t) override {
    if (done >= 3) cancel = true;
  }
};

TEST(Renderer, CancellationStopsBeforeTheRemainingTiles) {
  const RenderScene scene = test_scene();
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  std::atomic<bool> cancel{false};
  RenderOptions options;
  options.tile_size = 8;
  options.cancel = &cancel;
  CancelAfterThreeTiles canceller(cancel);
  options.observers = {&canceller};
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 1);
  const RenderResult result = render_image(scene, *backend, options);
  EXPECT_FALSE(result.complete());
  EXPECT_GE(result.tiles_done, 3u);
  EXPECT_LT(result.tiles_done, result.tiles_total);
}

// Observers see the film once at the end, whether the render finishes, is cancelled or fails.
TEST(Renderer, ObserversSeeTheFilmOnceAtTheEndHoweverTheRenderEnds) {
  const RenderScene scene = test_scene();
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  struct Ending final : RenderObserver {
    int calls = 0;
    bool complete = false;
    std::size_t items_in = 0;
    int passes_merged = 0;
    void render_ended(const ProgressiveFilm& film, bool whole) override {
      ++calls;
      complete = whole;
      items_in = film.items_in();
      passes_merged = film.passes_merged();
    }
  };
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 1);
  RenderOptions options;
  options.tile_size = 8;

  Ending finished;
  options.observers = {&finished};
  const RenderResult whole = render_image(scene, *backend, options);
  EXPECT_EQ(finished.calls, 1);
  EXPECT_TRUE(finished.complete);
  EXPECT_EQ(finished.items_in, whole.tiles_total);
  EXPECT_EQ(finished.passes_merged, whole.passes_total);

  std::atomic<bool> cancel{false};
  CancelAfterThreeTiles canceller(cancel);
  Ending cancelled;
  options.cancel = &cancel;
  options.observers = {&canceller, &cancelled};
  const RenderResult partial = render_image(scene, *backend, options);
  EXPECT_EQ(cancelled.calls, 1);
  EXPECT_FALSE(cancelled.complete);
  EXPECT_EQ(cancelled.items_in, partial.tiles_done);
  options.cancel = nullptr;

  // An executor that renders two items, then fails as a job whose rank died does.
  struct FailingExecutor final : TileExecutor {
    void execute(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink) override {
      TileRenderer::Workspace workspace;
      for (int i = 0; i < 2; ++i) {
        const std::size_t index = *source.next();
        sink.put(renderer.render(index, grid.tile(index), workspace));
      }
      throw RuntimeError("a rank died");
    }
  } failing;
  Ending failed;
  options.tile_executor = &failing;
  options.observers = {&failed};
  EXPECT_THROW(render_image(scene, *backend, options), RuntimeError);
  EXPECT_EQ(failed.calls, 1);
  EXPECT_FALSE(failed.complete);
  EXPECT_EQ(failed.items_in, 2u);
}

// A backend that answers as the one it wraps and counts the rays it is asked to trace once it
// has been told it is freed.
class ReleasableBackend final : public Backend {
 public:
  explicit ReleasableBackend(const Backend& traced) : traced_(traced) {}
  std::string_view name() const override { return traced_.name(); }
  bool intersect(const Ray& ray, Hit& hit) const override {
    count_late_call();
    return traced_.intersect(ray, hit);
  }
  bool occluded(const Ray& ray) const override {
    count_late_call();
    return traced_.occluded(ray);
  }
  BackendStats stats() const override { return traced_.stats(); }
  void release() { released_ = true; }
  int late_calls() const { return late_calls_; }

 private:
  void count_late_call() const {
    if (released_) ++late_calls_;
  }
  const Backend& traced_;
  std::atomic<bool> released_{false};
  mutable std::atomic<int> late_calls_{0};
};

TEST(Renderer, TracingDoneIsCalledOnceAfterTheLastRay) {
  RenderScene scene = test_scene();
  scene.render.spp = 16;
  scene.render.sampler = SamplerKind::kSobol;  // several passes
  const auto traced = make_backend(BackendKind::kNative, scene, {});
  ReleasableBackend backend(*traced);
  RenderOptions options;
  options.tile_size = 16;
  int calls = 0;
  options.tracing_done = [&] {
    ++calls;
    backend.release();
  };
  tbb::global_control cap(tbb::global_control::max_allowed_parallelism, 2);
  const RenderResult result = render_image(scene, backend, options);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(backend.late_calls(), 0);
  EXPECT_GT(result.passes_done, 1);
  // Releasing the backend there leaves the image as it is without the call.
  options.tracing_done = nullptr;
  EXPECT_TRUE(bit_identical(result.image, render_image(scene, *traced, options).image));
}

TEST(Renderer, AovLayersHavePlausibleValues) {
  const RenderScene scene = test_scene();
  const RenderResult r = render_with(scene, 2, 16, {Aov::kAlbedo, Aov::kNormal, Aov::kDepth, Aov::kObjectId});
  const std::vector<std::string> expected{"R",   "G",   "B",   "albedo.R", "albedo.G",    "albedo.B",
                                          "N.X", "N.Y", "N.Z", "depth.Z",  "object_id.id"};
  ASSERT_EQ(r.image.channels, expected);
  int hit_pixels = 0;
  for (int y = 0; y < r.image.height; ++y)
    for (int x = 0; x < r.image.width; ++x) {
      const float depth = r.image.at(x, y, 9);
      if (depth <= 0.0f) continue;
      ++hit_pixels;
      const Vec3 n{r.image.at(x, y, 6), r.image.at(x, y, 7), r.image.at(x, y, 8)};
      EXPECT_NEAR(length(n), 1.0f, 1e-4f);
      EXPECT_LT(depth, 40.0f);
    }
  EXPECT_GT(hit_pixels, 100);
}

// A render that keeps only the colour sums it in a loop of its own: the colour must be the one a
// render with every layer gives.
TEST(Renderer, ColourIsTheSameWithAndWithoutLayers) {
  const RenderScene scene = test_scene();
  const RenderResult plain = render_with(scene, 2, 16);
  const RenderResult layered =
      render_with(scene, 2, 16, {Aov::kAlbedo, Aov::kHalves, Aov::kVariance, Aov::kDepth, Aov::kObjectId});
  ASSERT_EQ(plain.image.channels.size(), 3u);
  ASSERT_GT(layered.image.channels.size(), 3u);
  int lit = 0;
  for (int y = 0; y < plain.image.height; ++y)
    for (int x = 0; x < plain.image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(plain.image.at(x, y, c), layered.image.at(x, y, c)) << x << "," << y << " channel " << c;
        lit += plain.image.at(x, y, c) > 0.0f;
      }
  EXPECT_GT(lit, 100);
}

}  // namespace renderer_test
}  // namespace rtpro
