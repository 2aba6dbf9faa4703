#include "rtpro/distributed/distributed_tile_executor.h"

namespace rtpro {

DistributedTileExecutor::DistributedTileExecutor(Communicator& communicator, PrestartedThread* render_thread,
                                                 std::chrono::milliseconds rank_timeout)
    : communicator_(communicator), render_thread_(render_thread), rank_timeout_(rank_timeout) {}

void DistributedTileExecutor::execute(const TileRenderer& renderer, const TileGrid& grid, TileSource& source,
                                      TileSink& sink) {
  ranks_ = lead_distributed_render(communicator_, renderer, grid, source, sink, render_thread_, rank_timeout_);
}

}  // namespace rtpro
