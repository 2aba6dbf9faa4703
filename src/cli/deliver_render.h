#pragma once
// The last stage of `rtpro render`: the rendered image finished (cropped, denoised, exposed) and
// written with its metadata (beside the output when the render was interrupted), the journal
// removed once the image is whole, the statistics, and the final message.
#include "log.h"
#include "render_request.h"
#include "render_session.h"
#include "rtpro/render/renderer.h"

#include <chrono>
#include <cstddef>

namespace rtpro::cli {

// When the command started, the seconds the scene took to read and build, and the peak resident
// set size by then.
struct RenderTimes {
  std::chrono::steady_clock::time_point start;
  double load_seconds = 0.0;
  std::size_t peak_rss_after_load_bytes = 0;
};

// The exit code: kExitOk, or kExitInterrupted when the image written is partial.
int deliver_render(const RenderRequest& request, RenderSession& session, RenderResult&& result,
                   const RenderTimes& times, Log& log);

}  // namespace rtpro::cli
