// One render of `rtpro render` as a pipeline: the request checked, the scene loaded, the image
// rendered, the image delivered.
#include "run_render.h"

#include "deliver_render.h"
#include "interrupt.h"
#include "load_scene.h"
#include "log.h"
#include "render_request.h"
#include "render_session.h"
#include "spared_inputs.h"
#include "rtpro/scene/scene_inputs.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstddef>

namespace rtpro::cli {

int run_render(const RenderCommandOptions& o, Communicator* job) {
  RenderTimes times{.start = std::chrono::steady_clock::now()};
  Log log(render_log_level(o, job));
  const RenderRequest request = parse_render_request(o, job, log);
  // Must exist before any TBB or Embree work so the cap really holds.
  const tbb::global_control thread_cap(tbb::global_control::max_allowed_parallelism,
                                       static_cast<std::size_t>(request.threads));
  // The files the scene names are spared before loading it, the files those read once it is loaded.
  const LoadedScene loaded = load_scene(request.scene, &log, [&](const SceneDescription& description) {
    if (request.leader) check_outputs_spare_inputs(request, named_inputs(description));
  });
  if (request.leader)
    check_outputs_spare_inputs(request, scene_inputs(loaded.description, loaded.report, loaded.scene));
  times.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - times.start).count();

  RenderSession session(request, loaded, job, log);
  if (!request.leader) return session.follow();
  // Held until the image is written: a first Ctrl-C stops the render, a second ends the process.
  const InterruptGuard interrupt;
  RenderResult result = session.render();
  return deliver_render(request, session, std::move(result), times, log);
}

}  // namespace rtpro::cli
