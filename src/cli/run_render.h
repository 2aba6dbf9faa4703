#pragma once
// One render of `rtpro render`, one frame of --frames: the options checked, the scene read and
// built, the image rendered (alone or with the other ranks of an MPI job) and written.
#include "render_command_options.h"
#include "rtpro/distributed/communicator.h"

namespace rtpro::cli {

// `job` is the MPI job when mpirun started more than one rank: rank 0 leads (and alone writes the
// image, the journal and the statistics), the others follow and say nothing unless they fail.
// Returns the exit code.
int run_render(const RenderCommandOptions& o, Communicator* job);

}  // namespace rtpro::cli
