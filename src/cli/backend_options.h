#pragma once
// The backend options of `rtpro render` and `rtpro crosscheck`, defined once: the Embree build
// quality parsed straight into its enum and robust traversal as an on/off flag pair.
#include "rtpro/backend/backend.h"

#include <CLI/CLI.hpp>

namespace rtpro::cli {

// --embree-quality low|medium|high and --embree-robust / --no-embree-robust, into `options`
// (whose values are the defaults shown in --help).
void add_embree_options(CLI::App& command, BackendOptions& options);

}  // namespace rtpro::cli
