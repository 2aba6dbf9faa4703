#pragma once
// One image rendered by the ranks of a job. Rank 0 leads: it hands tiles out on request (a few
// per worker thread, so no rank waits long and none holds much), renders with its own workers
// too, and puts every finished tile in its sink as it arrives (the image, the resume journal, the
// progress). The other ranks follow: they ask for tiles, render them and send each back as soon as
// it is done, holding nothing but the tiles in flight. A tile's pixels depend on its region alone,
// so the image is bit-identical for any number of ranks, threads and hand-out order.
#include "rtpro/distributed/communicator.h"
#include "rtpro/distributed/prestarted_thread.h"
#include "rtpro/job/job_identity.h"
#include "rtpro/render/tile_renderer.h"
#include "rtpro/render/tiles.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

namespace rtpro {

// What one rank did, for --stats: thread-seconds busy rendering tiles and idle waiting for them.
struct RankStats {
  int rank = 0;
  std::uint64_t tiles = 0;
  RayCounts rays;
  double busy_seconds = 0.0;
  double idle_seconds = 0.0;
  std::uint64_t bytes_sent = 0;
  // Rank 0 only: tiles other ranks sent it, and the CPU time its talking thread spent handing out
  // and taking in tiles (the scheduler's own cost; its capacity is about remote_tiles / this).
  std::uint64_t remote_tiles = 0;
  double scheduler_seconds = 0.0;
};

// How long a rank may send nothing while the ranks render (--rank-timeout) before the job ends
// as if it had died; zero: never. Every rank says it is alive several times a second.
inline constexpr std::chrono::milliseconds kDefaultRankTimeout{60000};

// Before any work: rank 0 gathers every rank's identity and throws InputError naming the first
// rank whose identity differs from its own, and how; the other ranks wait for rank 0's word.
// Every rank loads the scene before it gets here, so a rank that is stopped, hung or still
// loading holds the others: after `start_timeout` (--start-timeout; zero: wait for ever) of
// waiting, rank 0 throws RuntimeError naming the ranks it has not heard from, and another rank
// one saying rank 0 did not answer. It is not --rank-timeout: loading times differ between nodes
// by far more than a rendering rank's silences.
void agree_on_job(Communicator& communicator, const JobIdentity& identity,
                  std::chrono::milliseconds start_timeout = std::chrono::milliseconds(0));

// Rank 0: renders the tiles `source` hands out, with its workers and the other ranks, into `sink`;
// returns every rank's figures (indexed by rank) once all have finished. Stops handing out tiles
// when the source does (it checks the cancel flag).
// Rank 0's own workers run on `render_thread` when given (see prestarted_thread.h), else on a
// thread created here. Throws RuntimeError naming a rank silent for longer than `rank_timeout`
// (after rank 0's workers finish their tiles in flight, so the sink has them).
std::vector<RankStats> lead_distributed_render(Communicator& communicator, const TileRenderer& renderer,
                                               const TileGrid& grid, TileSource& source, TileSink& sink,
                                               PrestartedThread* render_thread = nullptr,
                                               std::chrono::milliseconds rank_timeout = kDefaultRankTimeout);

// Other ranks: renders what rank 0 hands out until it has no more, or until `cancel` becomes true
// (the tiles in flight are still finished and sent). It keeps about 20 ms of rendering queued at
// its measured speed per tile, for each of its `threads`. Returns once rank 0 has every rank's
// tiles (so the next frame's messages never meet this one's); throws RuntimeError when rank 0,
// once heard from, is silent for longer than `rank_timeout`.
void follow_distributed_render(Communicator& communicator, const TileRenderer& renderer, const TileGrid& grid,
                               int threads, const std::atomic<bool>* cancel = nullptr,
                               std::chrono::milliseconds rank_timeout = kDefaultRankTimeout);

// Load imbalance: the busiest rank's busy time over the mean (1 is perfect balance).
double load_imbalance(const std::vector<RankStats>& ranks);

}  // namespace rtpro
