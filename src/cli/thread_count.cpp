#include "thread_count.h"

#include "rtpro/core/error.h"

#include <algorithm>
#include <thread>

namespace rtpro::cli {

int worker_thread_count(std::optional<int> requested) {
  if (requested && *requested < 0) throw InputError("--threads must be >= 0 (0: all cores)");
  if (requested.value_or(0) > 0) return *requested;
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace rtpro::cli
