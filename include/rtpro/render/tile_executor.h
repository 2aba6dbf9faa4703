#pragma once
// Who renders a render's work items. Without one, this process's workers do (render_tiles), one
// pass at a time; an executor may share them with other processes (a distributed render), and is
// then given every pass's items in one go, so other processes render ahead while the film waits
// for a pass's last tile.
#include "rtpro/render/tile_renderer.h"
#include "rtpro/render/tiles.h"

namespace rtpro {

class TileExecutor {
 public:
  virtual ~TileExecutor() = default;

  // Renders the work items `source` hands out with `renderer` into `sink`; returns once the
  // source has none left and every item handed out is in the sink.
  virtual void execute(const TileRenderer& renderer, const TileGrid& grid, TileSource& source, TileSink& sink) = 0;
};

}  // namespace rtpro
