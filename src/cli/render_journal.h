#pragma once
// The resume journal of one `rtpro render`: what identifies the job (scene files and every setting
// that changes a pixel), and opening the journal beside the output, read back with --resume.
#include "log.h"
#include "rtpro/backend/backend.h"
#include "rtpro/job/job_identity.h"
#include "rtpro/job/journal_owner.h"
#include "rtpro/job/tile_journal.h"
#include "rtpro/render/adaptive_sampling.h"
#include "rtpro/render/film.h"
#include "rtpro/render/render_observer.h"
#include "rtpro/render/tiles.h"
#include "rtpro/scene/render_scene.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace rtpro::cli {

// What a pixel depends on besides the scene's files, as the render command knows it.
struct RenderJobSettings {
  std::vector<std::string> overrides;  // the scene overrides in command-line order, as typed
  std::string backend;
  BackendOptions backend_options;
  PixelRegion region;
  int tile_size = 0;
  std::vector<std::string> channels;
  AdaptiveSampling adaptive;
  bool compact_normals = false;
  std::uint32_t piece_triangles = 0;
};

JobIdentity render_job_identity(const SceneDescription& description, const SceneBuildReport& report,
                                const RenderScene& scene, const RenderJobSettings& settings);

// The journal of a render, kept as it goes: each newly rendered work item is appended, and once
// the journal holds twice the film, the sums so far replace the records they sum (every pass's
// records would make the journal spp/step times the film).
//
// Items finished before `record_from` are not appended: writing the film's worth of records costs
// a short render an eighth of its time (the 1-spp dragon frame: 10 of 85 ms), for a resume that
// would save less than the delay. The first merged pass after it, or an interrupted render's end,
// writes the film's sums instead; a render killed before then resumes from the records it has.
struct OpenedJournal final : RenderObserver {
  std::unique_ptr<JournalOwner> owner;  // held until the render ends (declared first: released last)
  std::unique_ptr<TileJournal> journal;
  std::vector<TileResult> finished;  // work items read back with --resume
  std::chrono::steady_clock::time_point record_from{};

  void tile_result(const TileResult& item) override;
  void pass_merged(int pass, const ProgressiveFilm& film) override;
  void render_ended(const ProgressiveFilm& film, bool complete) override;

 private:
  // Whether an item went unrecorded since the journal last took the film's sums. Set by worker
  // threads; moved only with the journal, before the render starts.
  struct Flag {
    std::atomic<bool> value{false};
    Flag() = default;
    Flag(Flag&& other) noexcept : value(other.value.load()) {}
    Flag& operator=(Flag&& other) noexcept {
      value = other.value.load();
      return *this;
    }
  };
  Flag unrecorded_;
};

// Takes the journal `file` (beside the output) for this render (an InputError when another render
// owns it, or when something other than a regular file is at its name). With `resume`, reads the
// journal (none: every tile is rendered, with a warning) and refuses one of another job with an
// InputError listing what differs. Then starts the journal afresh with the tiles kept, so torn or
// corrupt records are gone from it.
OpenedJournal open_render_journal(const std::filesystem::path& file, const JobIdentity& identity, const TileGrid& grid,
                                  int channel_count, bool resume, Log& log);

}  // namespace rtpro::cli
