#include "rtpro/render/renderer.h"

#include "rtpro/core/error.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/core/huge_page_buffer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <string>

namespace rtpro {

void render_tiles(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink) {
  // One long-lived task per worker, each pulling tiles until the source runs dry: the source, not
  // TBB's partitioner, decides the order, which is what a distributed scheduler needs.
  const int workers = tbb::this_task_arena::max_concurrency();
  tbb::parallel_for(tbb::blocked_range<int>(0, workers, 1), [&](const tbb::blocked_range<int>& slots) {
    set_tracing_fp_mode();
    TileRenderer::Workspace workspace;
    for (int slot = slots.begin(); slot != slots.end(); ++slot)
      while (const std::optional<std::size_t> index = source.next())
        sink.put(renderer.render(*index, grid.tile(*index), workspace));
  });
}

namespace {

// The film's output, in huge pages: with 4 KiB pages a 1024² RGB image is 3,072 page faults of
// ~13 µs each on these virtual machines, written by one thread after the last tile (40 ms of a
// 200 ms frame on two threads).
Image film_output_image(int width, int height, std::vector<std::string> channels) {
  Image image;
  image.width = width;
  image.height = height;
  image.channels = std::move(channels);
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * image.channels.size();
  image.data.reserve(count);
  if (count * sizeof(float) >= HugePageAllocator<float>::kLarge)
    advise_huge_pages(image.data.data(), count * sizeof(float));
  image.data.resize(count);
  return image;
}

using Clock = std::chrono::steady_clock;

// The listed work items once each, in order; stops when `cancel` becomes true, or at the deadline
// for items from `deadline_from` on (the first pass always finishes).
class PassItemSource final : public TileSource {
 public:
  PassItemSource(std::vector<std::size_t> items, const std::atomic<bool>* cancel,
                 std::optional<Clock::time_point> deadline, std::size_t deadline_from)
      : items_(std::move(items)), cancel_(cancel), deadline_(deadline), deadline_from_(deadline_from) {}
  std::optional<std::size_t> next() override {
    if (cancel_ && cancel_->load(std::memory_order_relaxed)) return std::nullopt;
    const std::size_t position = next_.fetch_add(1, std::memory_order_relaxed);
    if (position >= items_.size()) return std::nullopt;
    if (deadline_ && items_[position] >= deadline_from_ && Clock::now() >= *deadline_) {
      next_.store(items_.size());
      return std::nullopt;
    }
    return items_[position];
  }
  std::optional<std::size_t> remaining() const override {
    return items_.size() - std::min(next_.load(), items_.size());
  }

 private:
  std::vector<std::size_t> items_;
  const std::atomic<bool>* cancel_;
  std::optional<Clock::time_point> deadline_;
  std::size_t deadline_from_;
  std::atomic<std::size_t> next_{0};
};

// The image the observers that want one are shown: after each tile of the first pass, and after
// each merged pass. Calls come one at a time.
class PreviewImage {
 public:
  PreviewImage(const RenderScene& scene, const FilmLayout& layout, const SumLayout& sums,
               const std::vector<RenderObserver*>& observers)
      : layout_(layout), sums_(sums) {
    for (RenderObserver* observer : observers)
      if (observer->wants_images()) viewers_.push_back(observer);
    if (!viewers_.empty()) image_ = Image(scene.camera.width, scene.camera.height, layout.channels());
  }
  bool wanted() const { return !viewers_.empty(); }

  // A first-pass tile alone: the film holds nothing before it.
  void show_tile(const TileResult& item) {
    const std::lock_guard lock(mutex_);
    const auto channels = static_cast<std::size_t>(layout_.channel_count());
    const float* pixel_sums = item.pixels.data();
    for (int y = item.region.y0; y < item.region.y1; ++y)
      for (int x = item.region.x0; x < item.region.x1; ++x, pixel_sums += sums_.floats())
        layout_.resolve(sums_.load(pixel_sums), std::span<float>(&image_.at(x, y, 0), channels));
    show(item.region);
  }
  void show_film(const ProgressiveFilm& film) {
    const std::lock_guard lock(mutex_);
    film.resolve(layout_, image_);
    show(film.grid().region());
  }

 private:
  void show(const PixelRegion& changed) {
    for (RenderObserver* viewer : viewers_) viewer->pass_image(image_, changed);
  }

  const FilmLayout& layout_;
  const SumLayout& sums_;
  std::vector<RenderObserver*> viewers_;
  Image image_;
  std::mutex mutex_;
};

// Finished work items go to the observers (a journal keeps them), then into the film. Tiles of the
// first pass go to the preview as they come, too (a one-pass render shows its progress).
class FilmSink final : public TileSink {
 public:
  FilmSink(ProgressiveFilm& film, const std::vector<RenderObserver*>& observers, PreviewImage& preview)
      : film_(film), observers_(observers), preview_(preview) {}
  void put(TileResult&& item) override {
    for (RenderObserver* observer : observers_) observer->tile_result(item);
    if (preview_.wanted() && item.index < film_.grid().tiles_per_pass() && !item.cumulative) preview_.show_tile(item);
    film_.add(std::move(item));
    const std::size_t done = done_.fetch_add(1) + 1;
    for (RenderObserver* observer : observers_) observer->tile_done(done, film_.grid().count());
  }
  void count_journal_items(std::size_t items) { done_ += items; }
  std::size_t done() const { return done_.load(); }

 private:
  ProgressiveFilm& film_;
  const std::vector<RenderObserver*>& observers_;
  PreviewImage& preview_;
  std::atomic<std::size_t> done_{0};
};

// The journal's items, cumulative ones first, or none when they do not fit together.
std::vector<const TileResult*> usable_journal_items(std::span<const TileResult> items, const TileGrid& grid) {
  std::vector<const TileResult*> cumulative, partial;
  std::vector<bool> seen(grid.count(), false);
  for (const TileResult& item : items) {
    if (item.index >= grid.count() || item.region.x0 != grid.tile(item.index).x0 ||
        item.region.y0 != grid.tile(item.index).y0)
      throw std::logic_error("render_image: a journal item is not a work item of this grid");
    (item.cumulative ? cumulative : partial).push_back(&item);
  }
  if (!cumulative.empty()) {
    const int pass = grid.pass(cumulative.front()->index);
    std::vector<bool> tile_seen(grid.tiles_per_pass(), false);
    for (const TileResult* item : cumulative) {
      if (grid.pass(item->index) != pass || tile_seen[item->index % grid.tiles_per_pass()]) return {};
      tile_seen[item->index % grid.tiles_per_pass()] = true;
    }
    if (cumulative.size() != grid.tiles_per_pass()) return {};
  }
  cumulative.insert(cumulative.end(), partial.begin(), partial.end());
  return cumulative;
}

}  // namespace

PixelRegion checked_region(const RenderScene& scene, const RenderOptions& options) {
  const int width = scene.camera.width, height = scene.camera.height;
  const PixelRegion region = options.region.value_or(PixelRegion{0, 0, width, height});
  if (region.x0 < 0 || region.y0 < 0 || region.x1 > width || region.y1 > height || region.width() <= 0 ||
      region.height() <= 0)
    throw InputError("region " + std::to_string(region.x0) + "," + std::to_string(region.y0) + "," +
                     std::to_string(region.x1) + "," + std::to_string(region.y1) + " is empty or outside the " +
                     std::to_string(width) + "x" + std::to_string(height) + " image");
  if (options.tile_size <= 0) throw InputError("tile size must be positive");
  return region;
}

SumLayout render_sums(const RenderOptions& options) {
  const bool adaptive = options.adaptive.threshold > 0.0f;
  ExtraSums extra;
  switch (options.adaptive.metric) {
    case NoiseMetric::kCycles: extra.even_half = adaptive; break;
    case NoiseMetric::kRelMse: extra.squares = adaptive; break;
  }
  return SumLayout(options.aovs, extra);
}

RenderResult render_image(const RenderScene& scene, const Backend& backend, const RenderOptions& options) {
  const auto start = Clock::now();
  const TileGrid grid = render_grid(scene, checked_region(scene, options), options.tile_size);
  const FilmLayout layout(options.aovs);
  const SumLayout sums = render_sums(options);
  // Destroyed before tracing_done: nothing refers to the backend after it.
  std::optional<TileRenderer> renderer(std::in_place, scene, backend, grid, sums, options.textures,
                                       options.environment);
  if (options.adaptive.threshold > 0.0f && options.tile_executor)
    throw std::logic_error("render_image: adaptive sampling decides in this process; a tile executor cannot follow it");

  ProgressiveFilm film(grid, sums);
  PreviewImage preview(scene, layout, sums, options.observers);
  RenderResult result;
  Clock::time_point last_merge = start;
  film.on_pass_merged = [&](int pass) {
    const Clock::time_point now = Clock::now();
    result.pass_seconds.push_back(std::chrono::duration<double>(now - last_merge).count());
    last_merge = now;
    for (RenderObserver* observer : options.observers) observer->pass_merged(pass, film);
    if (preview.wanted()) preview.show_film(film);
  };
  FilmSink sink(film, options.observers, preview);
  const std::vector<const TileResult*> journal = usable_journal_items(options.journal_items, grid);
  for (const TileResult* item : journal) film.add(TileResult(*item));
  sink.count_journal_items(journal.size());
  result.pass_seconds.clear();  // the journal's passes cost nothing here
  last_merge = Clock::now();

  std::optional<Clock::time_point> deadline;
  if (options.time_limit_seconds > 0.0)
    deadline =
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options.time_limit_seconds));
  const auto unrendered = [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> items;
    for (std::size_t index = first; index < last; ++index)
      if (!film.has(index)) items.push_back(index);
    return items;
  };
  const auto execute = [&](TileSource& source) {
    try {
      if (options.tile_executor) options.tile_executor->execute(*renderer, grid, source, sink);
      else render_tiles(*renderer, grid, source, sink);
    } catch (...) {
      // The render failed (a rank of a job died, say): the observers still see the film as it
      // stands, so that a journal keeps what was finished for --resume. An observer's own failure
      // gives way to the render's.
      for (RenderObserver* observer : options.observers) {
        try {
          observer->render_ended(film, false);
        } catch (...) {
        }
      }
      throw;
    }
  };

  result.passes_total = grid.passes();
  result.tiles_total = grid.count();
  bool deadline_passed = false;
  if (options.tile_executor) {
    // Every pass in one go: other processes render ahead while the film waits for a pass's last tile.
    PassItemSource source(unrendered(0, grid.count()), options.cancel, deadline, grid.tiles_per_pass());
    execute(source);
    deadline_passed = deadline && Clock::now() >= *deadline;
  } else {
    std::vector<std::uint8_t> active;
    const std::size_t tiles = grid.tiles_per_pass();
    for (int pass = film.passes_merged(); pass < grid.passes(); pass = film.passes_merged()) {
      if (options.adaptive.threshold > 0.0f && pass > 0) {
        if (active_pixels(film, options.adaptive, active) == 0) {
          result.stop = RenderStop::kConverged;
          break;
        }
        renderer->set_active_pixels(&active);
      }
      // The first pass always finishes: a time limit shows whole passes.
      const std::optional<Clock::time_point> pass_deadline = pass > 0 ? deadline : std::nullopt;
      if (pass_deadline && Clock::now() >= *pass_deadline) {
        deadline_passed = true;
        break;
      }
      PassItemSource source(
          unrendered(static_cast<std::size_t>(pass) * tiles, static_cast<std::size_t>(pass + 1) * tiles),
          options.cancel, pass_deadline, tiles);
      execute(source);
      if (film.passes_merged() <= pass) {
        deadline_passed = pass_deadline && Clock::now() >= *pass_deadline;
        break;
      }
    }
  }
  renderer.reset();
  if (options.tracing_done) options.tracing_done();
  result.passes_done = film.passes_merged();
  if (result.stop != RenderStop::kConverged && result.passes_done < grid.passes())
    result.stop = deadline_passed && result.passes_done > 0 ? RenderStop::kTimeLimit : RenderStop::kInterrupted;

  result.image = film_output_image(scene.camera.width, scene.camera.height, layout.channels());
  result.samples = result.passes_done > 0 ? film.resolve(layout, result.image)
                                          : film.resolve_with_partial_pass(layout, result.image);
  result.tiles_done = sink.done();
  result.rays = film.rays();
  result.nan_samples = film.nan_samples();
  for (RenderObserver* observer : options.observers) observer->render_ended(film, result.complete());
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace rtpro
