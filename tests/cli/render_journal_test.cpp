// The render command's journal leaves out the work items finished before `record_from`, and
// records the film's sums instead at the first merged pass after it, or when an interrupted render
// ends; from `record_from` on it appends each item as it comes.
#include "render_journal.h"

#include "rtpro/backend/backend.h"
#include "rtpro/render/progressive_film.h"
#include "rtpro/render/renderer.h"
#include "rtpro/render/tile_renderer.h"
#include "test_fixtures.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>

namespace rtpro::cli {
namespace {

using Clock = std::chrono::steady_clock;

struct JournaledRender {
  RenderScene scene;
  std::unique_ptr<Backend> backend;
  TileGrid grid;
  SumLayout sums;
  std::vector<TileResult> items;  // every work item, in order
  std::filesystem::path file;
  OpenedJournal journal;

  // Path traced at 16 spp: passes of 1, 1, 2, 4, 4 and 4 samples, 6 tiles each.
  JournaledRender()
      : scene(path_scene()), backend(make_backend(BackendKind::kNative, scene, {})),
        grid(render_grid(scene, {0, 0, 40, 28}, 16)) {
    const TileRenderer renderer(scene, *backend, grid, sums);
    TileRenderer::Workspace workspace;
    for (std::size_t i = 0; i < grid.count(); ++i) items.push_back(renderer.render(i, grid.tile(i), workspace));
    file = test::scratch_dir() / "out.exr.rtpro-journal";
    Log log(LogLevel::kQuiet);
    JobIdentity identity;
    identity.set("scene", "journal test");
    journal = open_render_journal(file, identity, grid, sums.floats(), false, log);
  }
  static RenderScene path_scene() {
    RenderScene scene = test::random_mixed_scene(11, 40, 60, 2);
    test::set_camera(scene, 40, 28);
    scene.render.integrator = Integrator::kPath;
    scene.render.sampler = SamplerKind::kSobol;
    scene.render.spp = 16;
    return scene;
  }
  // The items the journal on disk holds, as --resume reads them.
  std::vector<TileResult> recorded() const { return read_journal(file, grid, sums.floats()).tiles; }
};

// A film rebuilt from the journal's records has `film`'s passes and resolves to its image, bit for bit.
void expect_journal_rebuilds(const JournaledRender& render, const ProgressiveFilm& film) {
  ProgressiveFilm rebuilt(render.grid, render.sums);
  for (TileResult& item : render.recorded()) rebuilt.add(std::move(item));
  EXPECT_EQ(rebuilt.passes_merged(), film.passes_merged());
  const FilmLayout layout({});
  Image expected(40, 28, layout.channels()), actual(40, 28, layout.channels());
  film.resolve_with_partial_pass(layout, expected);
  rebuilt.resolve_with_partial_pass(layout, actual);
  EXPECT_EQ(std::memcmp(actual.data.data(), expected.data.data(), expected.data.size() * sizeof(float)), 0);
  for (int y = 0; y < 28; ++y)
    for (int x = 0; x < 40; ++x) ASSERT_EQ(rebuilt.pixel(x, y).samples, film.pixel(x, y).samples) << x << "," << y;
}

TEST(RenderJournal, ItemsBeforeTheDelayAreRecordedAtTheFirstMergedPassAfterIt) {
  JournaledRender render;
  ASSERT_EQ(render.grid.passes(), 6);
  const std::size_t tiles = render.grid.tiles_per_pass();
  render.journal.record_from = Clock::now() + std::chrono::hours(1);
  ProgressiveFilm film(render.grid, render.sums);
  film.on_pass_merged = [&](int pass) { render.journal.pass_merged(pass, film); };
  const auto add = [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      render.journal.tile_result(render.items[i]);
      film.add(TileResult(render.items[i]));
    }
  };
  add(0, 2 * tiles + 1);  // two passes merged, one item of the third in
  EXPECT_TRUE(render.recorded().empty()) << "nothing is recorded before the delay";

  render.journal.record_from = Clock::now();
  add(2 * tiles + 1, 2 * tiles + 3);  // appended as they come, the third pass still open
  EXPECT_EQ(render.recorded().size(), 2u);
  add(2 * tiles + 3, 3 * tiles);  // the third pass merges: the film's sums replace the records
  EXPECT_EQ(film.passes_merged(), 3);
  const std::vector<TileResult> recorded = render.recorded();
  ASSERT_EQ(recorded.size(), tiles);
  for (const TileResult& item : recorded) EXPECT_TRUE(item.cumulative);
  expect_journal_rebuilds(render, film);

  add(3 * tiles, 3 * tiles + 2);  // from then on, item by item
  EXPECT_EQ(render.recorded().size(), tiles + 2);
}

TEST(RenderJournal, AnInterruptedRenderRecordsWhatItFinishedBeforeTheDelay) {
  JournaledRender render;
  const std::size_t tiles = render.grid.tiles_per_pass();
  render.journal.record_from = Clock::now() + std::chrono::hours(1);
  ProgressiveFilm film(render.grid, render.sums);
  film.on_pass_merged = [&](int pass) { render.journal.pass_merged(pass, film); };
  for (std::size_t i = 0; i < tiles + 3; ++i) {
    render.journal.tile_result(render.items[i]);
    film.add(TileResult(render.items[i]));
  }
  EXPECT_TRUE(render.recorded().empty());

  render.journal.render_ended(film, true);  // a complete render's journal is removed, not written
  EXPECT_TRUE(render.recorded().empty());
  render.journal.render_ended(film, false);
  EXPECT_EQ(render.recorded().size(), tiles + 3);  // the first pass's sums and the second's items
  expect_journal_rebuilds(render, film);
}

TEST(RenderJournal, WithoutADelayEveryItemIsAppendedAsItComes) {
  JournaledRender render;
  render.journal.record_from = Clock::now();
  ProgressiveFilm film(render.grid, render.sums);
  film.on_pass_merged = [&](int pass) { render.journal.pass_merged(pass, film); };
  for (std::size_t i = 0; i < 3; ++i) {
    render.journal.tile_result(render.items[i]);
    film.add(TileResult(render.items[i]));
    EXPECT_EQ(render.recorded().size(), i + 1);
  }
  render.journal.render_ended(film, false);
  EXPECT_EQ(render.recorded().size(), 3u) << "nothing left out: the interrupted render's journal is as it was";
}

}  // namespace
}  // namespace rtpro::cli
