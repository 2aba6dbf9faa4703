// The film merges whole passes in pass order, whatever order and thread its work items come from,
// and a journal's cumulative items rebuild it exactly.
#include "rtpro/render/progressive_film.h"

#include "rtpro/backend/backend.h"
#include "rtpro/render/adaptive_sampling.h"
#include "rtpro/render/renderer.h"
#include "rtpro/render/tile_renderer.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

namespace rtpro {
namespace progressive_film_test {

RenderScene path_scene() {
  RenderScene scene = test::random_mixed_scene(11, 40, 60, 2);
  test::set_camera(scene, 40, 28);
  scene.render.integrator = Integrator::kPath;
  scene.render.sampler = SamplerKind::kSobol;
  scene.render.spp = 16;  // passes of 1, 1, 2, 4, 4 and 4 samples
  return scene;
}

// The layers these tests resolve, and the sums the items carry for them.
const std::vector<Aov> kLayers{Aov::kAlbedo, Aov::kHalves, Aov::kSpp};
SumLayout layer_sums() { return SumLayout(kLayers, {}); }

// Every work item of the grid, rendered.
std::vector<TileResult> render_items(const RenderScene& scene, const Backend& backend, const TileGrid& grid) {
  const TileRenderer renderer(scene, backend, grid, layer_sums());
  TileRenderer::Workspace workspace;
  std::vector<TileResult> items;
  for (std::size_t i = 0; i < grid.count(); ++i) items.push_back(renderer.render(i, grid.tile(i), workspace));
  return items;
}

std::vector<float> resolved(const ProgressiveFilm& film, const RenderScene& scene) {
  const FilmLayout layout(kLayers);
  Image image(scene.camera.width, scene.camera.height, layout.channels());
  film.resolve(layout, image);
  return image.data;
}

TEST(ProgressiveFilm, MergesPassesInOrderWhateverOrderItemsArriveIn) {
  const RenderScene scene = path_scene();
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const TileGrid grid = render_grid(scene, {0, 0, 40, 28}, 16);
  ASSERT_EQ(grid.passes(), 6);
  std::vector<TileResult> items = render_items(scene, *backend, grid);

  ProgressiveFilm in_order(grid, layer_sums());
  std::vector<int> merged;
  in_order.on_pass_merged = [&](int pass) { merged.push_back(pass); };
  for (const TileResult& item : items) in_order.add(TileResult(item));
  EXPECT_EQ(merged, (std::vector<int>{0, 1, 2, 3, 4, 5}));

  std::mt19937 rng(5);
  std::shuffle(items.begin(), items.end(), rng);
  ProgressiveFilm shuffled(grid, layer_sums());
  int passes_seen = 0;
  shuffled.on_pass_merged = [&](int pass) {
    EXPECT_EQ(pass, passes_seen++);
    // A merged pass is whole: every pixel has the samples of every pass so far.
    const int expected = render_passes(scene).samples_through(pass);
    for (int y = 0; y < 28; ++y)
      for (int x = 0; x < 40; ++x) ASSERT_EQ(shuffled.pixel(x, y).samples, expected);
  };
  for (TileResult& item : items) shuffled.add(std::move(item));
  EXPECT_EQ(passes_seen, 6);
  const std::vector<float> a = resolved(in_order, scene), b = resolved(shuffled, scene);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);

  // The same as render_image, with other tiles and all threads.
  RenderOptions options;
  options.tile_size = 7;
  options.aovs = kLayers;
  const RenderResult result = render_image(scene, *backend, options);
  EXPECT_EQ(result.passes_done, 6);
  ASSERT_EQ(result.image.data.size(), a.size());
  EXPECT_EQ(std::memcmp(result.image.data.data(), a.data(), a.size() * sizeof(float)), 0);
}

TEST(ProgressiveFilm, JournalItemsRebuildTheFilmExactly) {
  const RenderScene scene = path_scene();
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const TileGrid grid = render_grid(scene, {0, 0, 40, 28}, 16);
  const std::vector<TileResult> items = render_items(scene, *backend, grid);
  const std::size_t tiles = grid.tiles_per_pass();

  ProgressiveFilm whole(grid, layer_sums());
  for (const TileResult& item : items) whole.add(TileResult(item));

  // Three passes merged and one tile of the fourth in: what a journal compacts to.
  ProgressiveFilm partial(grid, layer_sums());
  for (std::size_t i = 0; i < 3 * tiles + 1; ++i) partial.add(TileResult(items[i]));
  ASSERT_EQ(partial.passes_merged(), 3);
  std::vector<TileResult> journal;
  partial.visit_journal_items([&](const TileResult& item) { journal.push_back(item); });
  ASSERT_EQ(journal.size(), tiles + 1);
  for (std::size_t t = 0; t < tiles; ++t) EXPECT_TRUE(journal[t].cumulative);
  EXPECT_FALSE(journal.back().cumulative);

  ProgressiveFilm resumed(grid, layer_sums());
  for (const TileResult& item : journal) resumed.add(TileResult(item));
  EXPECT_EQ(resumed.passes_merged(), 3);
  for (std::size_t i = 0; i < grid.count(); ++i)
    if (!resumed.has(i)) resumed.add(TileResult(items[i]));
  EXPECT_EQ(resumed.passes_merged(), 6);
  const std::vector<float> a = resolved(whole, scene), b = resolved(resumed, scene);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
  EXPECT_EQ(resumed.rays().total(), whole.rays().total());
}

// resolve gives the samples the resolved sums hold: of the merged passes, or before the first pass
// is whole, of its tiles that are in (the others 0).
TEST(ProgressiveFilm, ResolveCountsTheSamplesOfTheMergedPasses) {
  const RenderScene scene = path_scene();
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const TileGrid grid = render_grid(scene, {0, 0, 40, 28}, 16);  // tiles of 16×16, 16×12, 8×16, 8×12
  const std::vector<TileResult> items = render_items(scene, *backend, grid);
  const std::size_t tiles = grid.tiles_per_pass();
  const FilmLayout layout(kLayers);
  Image image(scene.camera.width, scene.camera.height, layout.channels());

  ProgressiveFilm film(grid, layer_sums());
  film.add(TileResult(items[1]));  // the first pass's tile 1 alone: 16×16 of 40×28 pixels at 1 sample
  SampleCounts counts = film.resolve_with_partial_pass(layout, image);
  EXPECT_EQ(counts.min, 0);
  EXPECT_EQ(counts.max, 1);
  EXPECT_DOUBLE_EQ(counts.mean, items[1].region.pixel_count() / (40.0 * 28.0));

  for (std::size_t i = 0; i < 3 * tiles + 2; ++i)
    if (i != 1) film.add(TileResult(items[i]));
  ASSERT_EQ(film.passes_merged(), 3);  // two tiles of the fourth pass wait
  const int merged = render_passes(scene).samples_through(2);
  for (const SampleCounts& resolved : {film.resolve(layout, image), film.resolve_with_partial_pass(layout, image)}) {
    EXPECT_EQ(resolved.min, merged);
    EXPECT_EQ(resolved.max, merged);
    EXPECT_DOUBLE_EQ(resolved.mean, merged);
    EXPECT_TRUE(resolved.uniform());
  }
}

// A pixel masked out of a pass gets no samples in it; the others get the pass's.
TEST(ProgressiveFilm, PixelsOutOfTheMaskTakeNoSamples) {
  const RenderScene scene = path_scene();
  const auto backend = make_backend(BackendKind::kNative, scene, {});
  const TileGrid grid = render_grid(scene, {0, 0, 40, 28}, 16);
  const SumLayout sums;
  TileRenderer renderer(scene, *backend, grid, sums);
  std::vector<std::uint8_t> mask(40 * 28, 1);
  for (int x = 0; x < 40; ++x) mask[static_cast<std::size_t>(5 * 40 + x)] = 0;  // row 5
  renderer.set_active_pixels(&mask);
  TileRenderer::Workspace workspace;
  const std::size_t item = 3 * grid.tiles_per_pass();  // tile 0 of pass 3: samples 4..7
  const TileResult result = renderer.render(item, grid.tile(item), workspace);
  const PixelRegion& tile = result.region;
  for (int y = tile.y0; y < tile.y1; ++y)
    for (int x = tile.x0; x < tile.x1; ++x) {
      const PixelAccumulator acc =
          sums.load(result.pixels.data() + static_cast<std::size_t>((y - tile.y0) * tile.width() + (x - tile.x0)) *
                                               static_cast<std::size_t>(sums.floats()));
      EXPECT_EQ(acc.samples, y == 5 ? 0 : 4) << x << "," << y;
    }
}

// The error of a pixel whose samples agree is 0; one whose halves differ is not; the dilation
// keeps a converged pixel next to an unconverged one going.
TEST(AdaptiveSampling, ConvergedPixelsStopAndTheirNeighboursOfNoisyOnesGoOn) {
  PixelAccumulator flat;
  for (int s = 0; s < 32; ++s) flat.add(Color(0.5f), PrimaryHit{}, s);
  EXPECT_EQ(pixel_error(flat, NoiseMetric::kCycles), 0.0f);
  EXPECT_EQ(pixel_error(flat, NoiseMetric::kRelMse), 0.0f);
  PixelAccumulator noisy;
  for (int s = 0; s < 32; ++s) noisy.add(Color(s % 2 == 0 ? 1.0f : 0.0f), PrimaryHit{}, s);
  EXPECT_GT(pixel_error(noisy, NoiseMetric::kCycles), 0.5f);
  EXPECT_GT(pixel_error(noisy, NoiseMetric::kRelMse), 0.02f);

  const TileGrid grid({0, 0, 8, 1}, 8);
  TileResult item;
  item.region = grid.tile(0);
  const SumLayout sums({}, {.even_half = true});
  item.pixels.resize(static_cast<std::size_t>(8 * sums.floats()));
  for (int x = 0; x < 8; ++x) sums.store(x == 6 ? noisy : flat, item.pixels.data() + x * sums.floats());
  ProgressiveFilm film(grid, sums);
  film.add(std::move(item));
  std::vector<std::uint8_t> mask;
  EXPECT_EQ(active_pixels(film, {0.01f, 16}, mask), 3u);
  EXPECT_EQ(mask, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 1, 1}));
  // Below the minimum samples every pixel goes on.
  EXPECT_EQ(active_pixels(film, {0.01f, 64}, mask), 8u);
}

}  // namespace progressive_film_test
}  // namespace rtpro
