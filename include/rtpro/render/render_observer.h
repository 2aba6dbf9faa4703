#pragma once
// Who follows a render as it goes: progress counts the finished work items, a resume journal keeps
// each one and compacts itself after each merged pass, a live preview shows the image. The
// renderer tells every observer of RenderOptions, in their order; a method not overridden does
// nothing. Chosen once per render, so a virtual call per work item costs nothing that shows.
#include "rtpro/image/image.h"
#include "rtpro/render/progressive_film.h"
#include "rtpro/render/tiles.h"

#include <cstddef>

namespace rtpro {

class RenderObserver {
 public:
  virtual ~RenderObserver() = default;

  // From worker threads, with each newly rendered work item before it goes into the film.
  virtual void tile_result(const TileResult& /*item*/) {}
  // From worker threads, after each finished work item: the items done and the grid's total.
  virtual void tile_done(std::size_t /*done*/, std::size_t /*total*/) {}
  // After each merged pass, with its number and the film.
  virtual void pass_merged(int /*pass*/, const ProgressiveFilm& /*film*/) {}
  // Once, after the last work item, with the film as the render leaves it; `complete`: the image
  // is the render's whole (RenderResult::complete), not an interrupted one's. Also, with
  // `complete` false, when the render fails with an exception (before it propagates).
  virtual void render_ended(const ProgressiveFilm& /*film*/, bool /*complete*/) {}

  // Whether this observer takes pass_image: the renderer keeps a preview image only when one
  // does, as resolving it costs a pass over the film.
  virtual bool wants_images() const { return false; }
  // The image (full camera size) and the region that changed in it, after each tile of the first
  // pass (its pixels so far) and after each merged pass (the whole region: the passes so far).
  // One call at a time, from whichever thread finished the work.
  virtual void pass_image(const Image& /*image*/, const PixelRegion& /*changed*/) {}
};

}  // namespace rtpro
