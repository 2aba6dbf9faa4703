#pragma once
// --threads of every command that renders or filters: how many workers it runs.
#include <optional>

namespace rtpro::cli {

// The count asked for, or every core (at least one) for 0 or none given. Throws InputError for a
// negative count.
int worker_thread_count(std::optional<int> requested);

}  // namespace rtpro::cli
