// `rtpro render`: one render (run_render.h), or one per frame of --frames, in one process or in
// every rank of an MPI job.
#include "command.h"
#include "frame_sequence.h"
#include "log.h"
#include "render_command_options.h"
#include "run_render.h"
#include "scene_overrides.h"
#include "rtpro/core/error.h"
#include "rtpro/distributed/communicator.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <utility>

namespace rtpro::cli {

namespace {

// One render, or one per frame of --frames, each exactly the image that frame renders alone.
int run_renders(const RenderCommandOptions& o, Communicator* job) {
  Log log(o.quiet ? LogLevel::kQuiet : LogLevel::kNormal);
  if (o.frames.empty()) {
    if (has_frame_pattern(o.output))
      throw InputError("-o " + o.output + " holds a frame number pattern ('#'): give --frames, e.g. --frames 1-240");
    if (o.skip_existing && o.output != "-" && std::filesystem::exists(o.output)) {
      log.info("skipped: " + o.output + " exists (--skip-existing)");
      return kExitOk;
    }
    return run_render(o, job);
  }
  const FrameRange range = parse_frame_range(o.frames);
  if (!has_frame_pattern(o.output))
    throw InputError("--frames needs a frame number pattern in -o, e.g. -o out_####.exr");
  if (o.scene == "-") throw InputError("--frames reads the scene once per frame: it cannot come from standard input");
  if (!o.stats_json.empty() && !has_frame_pattern(o.stats_json))
    throw InputError("--stats-json with --frames needs a frame number pattern too, e.g. stats_####.json");
  for (const SceneOverride& set : o.scene_overrides)
    if (set.assignment.rfind("variables.frame=", 0) == 0) throw InputError(set.flag + ": --frames sets the frame");
  for (long frame : range.frames()) {
    RenderCommandOptions one = o;
    one.output = numbered_output(o.output, frame);
    one.stats_json = numbered_output(o.stats_json, frame);
    one.frame = frame;
    if (o.skip_existing && std::filesystem::exists(one.output)) {
      log.info("frame " + std::to_string(frame) + " skipped: " + one.output + " exists (--skip-existing)");
      continue;
    }
    one.scene_overrides.push_back(
        {"variables.frame=" + std::to_string(frame), "--frames (frame " + std::to_string(frame) + ")"});
    const int code = run_render(one, job);
    if (code != kExitOk) return code;
  }
  return kExitOk;
}

// Under mpirun every rank runs this. A rank that fails ends the whole job (MPI_Abort) with its
// exit code, so no rank waits for it; each finalizes MPI otherwise.
int run_renders_in_mpi_job(const RenderCommandOptions& o) {
  if (o.skip_existing)
    throw InputError("--skip-existing decides by files only rank 0 can see: not available under mpirun");
  std::unique_ptr<Communicator> job = join_mpi_job();
  const int rank = job->rank();
  try {
    const int code = run_renders(o, job->size() > 1 ? job.get() : nullptr);
    leave_mpi_job(std::move(job), std::chrono::milliseconds(static_cast<std::int64_t>(o.rank_timeout * 1000.0)));
    return code;
  } catch (const std::exception& e) {
    if (rank == 0) std::fprintf(stderr, "rtpro: error: %s\n", e.what());
    else std::fprintf(stderr, "rtpro: error on rank %d: %s\n", rank, e.what());
    std::fflush(stderr);
    job->abort(dynamic_cast<const InputError*>(&e) ? kExitInputError : kExitRuntimeFailure);
  }
  return kExitRuntimeFailure;  // not reached: abort() ends the process
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<RenderCommandOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to an image");
  add_render_options(*cmd, *o);
  cmd->callback([o, cmd, &action] {
    o->scene_overrides = command_line_overrides(*cmd);
    action = [o] { return launched_by_mpirun() ? run_renders_in_mpi_job(*o) : run_renders(*o, nullptr); };
  });
}

}  // namespace rtpro::cli
