#pragma once
// Limits every mesh loader enforces, so a hostile file fails cleanly instead of reaching the
// backends with values they cannot handle.
#include <cstdint>

namespace rtpro {

// Debian's Embree aborts on ray origins beyond ~1.8e18 (see notes/reliability.md); vertices far
// below that leave room for instance transforms and camera distances.
inline constexpr float kMaxAbsCoordinate = 1e16f;

// Vertex and triangle indices are uint32; ~0u stays free as a "none" marker.
inline constexpr std::uint64_t kMaxMeshElements = 0xFFFFFFFEull;

}  // namespace rtpro
