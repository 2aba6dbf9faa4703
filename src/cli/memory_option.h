#pragma once
// --max-memory, shared by `rtpro render` and `rtpro info`: the budget a render's up-front
// estimate (rtpro/scene/render_cost.h) is checked against.
#include <cstdint>
#include <string>

namespace rtpro::cli {

struct MemoryBudget {
  std::uint64_t bytes = 0;
  std::string source;           // for messages: "--max-memory 512" or "the default: ..."
  bool explicit_limit = false;  // given by the user: also Embree's BVH limit
};

// `text` in MiB as typed (empty: not given): the default budget when empty, no limit for 0.
// Anything but decimal digits (a sign, a fraction, 2^64) is an input error, never a wrapped value.
MemoryBudget parse_memory_budget(const std::string& text);

}  // namespace rtpro::cli
