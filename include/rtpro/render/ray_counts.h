#pragma once
// Rays traced, counted by kind: what the statistics report and what tile records and a rank's
// report carry. The kinds are a closed enum indexing one array, so a count is an indexed add in the
// integrators' loops and every reader and writer goes through the array in RayKind order.
#include <array>
#include <cstddef>
#include <cstdint>

namespace rtpro {

enum class RayKind : std::uint8_t { kCamera, kShadow, kReflection, kRefraction };
inline constexpr std::size_t kRayKindCount = 4;
inline constexpr std::array<RayKind, kRayKindCount> kRayKinds = {RayKind::kCamera, RayKind::kShadow,
                                                                 RayKind::kReflection, RayKind::kRefraction};

// The kind's name in statistics ("camera", "shadow", "reflection", "refraction"): the keys of
// `rays` in --stats-json, which benchmarks read.
const char* ray_kind_name(RayKind kind);

// In binary records (a tile record, a rank's done record) a RayCounts is its `by_kind` array as it
// is in memory: kRayKindCount 64-bit counts in RayKind order, the host's (little-endian) byte order.
struct RayCounts {
  std::array<std::uint64_t, kRayKindCount> by_kind{};

  std::uint64_t& operator[](RayKind kind) { return by_kind[static_cast<std::size_t>(kind)]; }
  std::uint64_t operator[](RayKind kind) const { return by_kind[static_cast<std::size_t>(kind)]; }
  std::uint64_t total() const {
    std::uint64_t sum = 0;
    for (const std::uint64_t count : by_kind) sum += count;
    return sum;
  }
  RayCounts& operator+=(const RayCounts& o) {
    for (std::size_t k = 0; k < kRayKindCount; ++k) by_kind[k] += o.by_kind[k];
    return *this;
  }
};
static_assert(sizeof(RayCounts) == kRayKindCount * sizeof(std::uint64_t), "records hold the counts and nothing else");

}  // namespace rtpro
