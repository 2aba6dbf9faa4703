#include "memory_option.h"

#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"

#include <charconv>
#include <cstdint>

namespace rtpro::cli {

MemoryBudget parse_memory_budget(const std::string& text) {
  if (text.empty())
    return {default_memory_budget(),
            "the default: the smaller of " + format_bytes(kDefaultMemoryBudgetCap) + " and the available memory",
            false};
  std::uint64_t mib = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), mib);
  constexpr std::uint64_t kMaxMib = std::uint64_t{1} << 40;  // 1 EiB: beyond any machine
  if (error != std::errc() || end != text.data() + text.size() || mib > kMaxMib)
    throw InputError("--max-memory '" + text + "': expected a size in MiB from 0 (no limit) to " +
                     std::to_string(kMaxMib));
  if (mib == 0) return {UINT64_MAX, "--max-memory 0", false};
  return {mib << 20, "--max-memory " + text, true};
}

}  // namespace rtpro::cli
