#pragma once
// The render stage of `rtpro render`: for a loaded scene, the backend built and the scene's images
// opened, the resume journal opened (the ranks of a job first agree they render the same thing),
// then the image rendered by this process or by the ranks of the job, with the progress, the live
// preview and the journal following it as observers. What the session holds lives until the
// image is delivered.
#include "load_scene.h"
#include "log.h"
#include "render_journal.h"
#include "render_request.h"
#include "scene_images.h"
#include "tev_client.h"
#include "rtpro/backend/backend.h"
#include "rtpro/distributed/communicator.h"
#include "rtpro/distributed/distributed_tile_executor.h"
#include "rtpro/distributed/prestarted_thread.h"
#include "rtpro/render/renderer.h"

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro::cli {

class RenderSession {
 public:
  // Refuses (InputError) a time limit or noise threshold for a one-pass render, then prepares
  // everything the render needs, in the order that keeps the image layer's load off its way.
  RenderSession(const RenderRequest& request, const LoadedScene& loaded, Communicator* job, Log& log);
  RenderSession(const RenderSession&) = delete;
  RenderSession& operator=(const RenderSession&) = delete;

  // Rank 0, or the only process: the image, stopping early at an interrupt (InterruptGuard), the
  // time limit or convergence, each said in the log.
  RenderResult render();
  // Every other rank of a job: renders what rank 0 hands out until it has no more; the exit code.
  int follow();

  const RenderScene& scene() const { return loaded_.scene; }
  // The backend's name and statistics, also once it is released.
  std::string_view backend_name() const { return backend_name_; }
  BackendStats backend_stats() const { return backend_ ? backend_->stats() : released_stats_; }
  // Frees the acceleration structure. render() does so as soon as its last ray is traced: the
  // film is resolved and the image made and written without it, so that its bytes and the
  // image's are never resident at once.
  void release_backend();
  // The process's peak resident set size when the backend was built: the scene and its
  // acceleration structure, with whatever their builds held at their peaks.
  std::size_t peak_rss_after_build_bytes() const { return peak_rss_after_build_bytes_; }
  // The journal kept for --resume; null without one.
  TileJournal* journal() { return journal_.journal.get(); }
  // Every rank's figures of a distributed render; empty for one process.
  std::vector<RankStats> ranks() const;

 private:
  void check_passes() const;
  void start_workers();
  void build_backend();
  void open_images();
  void open_journal();
  TileGrid grid() const;
  std::vector<RenderObserver*> observers(RenderObserver& progress);

  const RenderRequest& request_;
  const LoadedScene& loaded_;
  Communicator* job_;
  Log& log_;
  RenderOptions options_;
  std::optional<PrestartedThread> render_thread_;
  std::unique_ptr<Backend> backend_;
  std::string backend_name_;
  BackendStats released_stats_;
  std::size_t peak_rss_after_build_bytes_ = 0;
  SceneImages images_;
  std::unique_ptr<TevClient> preview_;
  OpenedJournal journal_;
  std::optional<DistributedTileExecutor> executor_;
};

}  // namespace rtpro::cli
