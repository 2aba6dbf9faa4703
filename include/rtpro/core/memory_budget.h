#pragma once
// How much memory one rtpro run may plan to use. Work whose size a small input can choose — an
// image resolution, instances multiplied through nesting, an image file's declared size — is
// estimated before anything is allocated and refused (an input error naming the limit) when the
// estimate exceeds the budget, instead of allocating gigabytes and failing minutes later.
#include <cstdint>
#include <string>

namespace rtpro {

// The default budget when the user gives none (--max-memory): the smaller of 4 GiB and the memory
// the system reports available (MemAvailable in /proc/meminfo) — generous for real scenes, and
// never more than the machine can give without swapping.
inline constexpr std::uint64_t kDefaultMemoryBudgetCap = std::uint64_t{4} << 30;
std::uint64_t default_memory_budget();

// MemAvailable in bytes, or 0 when the system does not say.
std::uint64_t available_memory();

// "1.5 GiB", "300.0 MiB", "12 KiB": sizes in messages.
std::string format_bytes(std::uint64_t bytes);

// a·b and a+b, saturating at UINT64_MAX instead of wrapping: counts multiplied out from a small
// file can exceed 64 bits, and a saturated count still compares as "too large".
std::uint64_t saturating_multiply(std::uint64_t a, std::uint64_t b);
std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b);

}  // namespace rtpro
