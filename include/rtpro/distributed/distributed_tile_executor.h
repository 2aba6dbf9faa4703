#pragma once
// Rank 0's way of rendering a render's work items in an MPI job: its own workers and the other
// ranks share them (lead_distributed_render), and the figures of every rank are kept for --stats.
#include "rtpro/distributed/communicator.h"
#include "rtpro/distributed/distributed_render.h"
#include "rtpro/distributed/prestarted_thread.h"
#include "rtpro/render/tile_executor.h"

#include <chrono>
#include <vector>

namespace rtpro {

class DistributedTileExecutor final : public TileExecutor {
 public:
  // `render_thread` and `rank_timeout` as for lead_distributed_render; the communicator and the
  // thread must outlive the executor.
  explicit DistributedTileExecutor(Communicator& communicator, PrestartedThread* render_thread = nullptr,
                                   std::chrono::milliseconds rank_timeout = kDefaultRankTimeout);

  void execute(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink) override;

  // Every rank's figures (indexed by rank) of the last execute; empty before one.
  const std::vector<RankStats>& ranks() const { return ranks_; }

 private:
  Communicator& communicator_;
  PrestartedThread* render_thread_;
  std::chrono::milliseconds rank_timeout_;
  std::vector<RankStats> ranks_;
};

}  // namespace rtpro
