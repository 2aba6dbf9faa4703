#pragma once
// Large meshes in spatially compact pieces. A BVH builder holds a temporary record per primitive
// while it builds (Embree: 32 bytes a triangle, a third of the dragon's build peak); a mesh built
// piece by piece, each piece its own BVH under the top one, holds one piece's records at a time.
// For that the pieces must be compact in space, or a ray would walk several overlapping ones:
// the dragon's file order cut into 8 runs gives boxes of 3.8 times the whole's surface area.
#include "rtpro/scene/mesh.h"

#include <cstdint>

namespace rtpro {

// The fewest triangles a piece may hold: smaller pieces cost more in the top-level tree than
// they save in the build.
inline constexpr std::uint32_t kMinPieceTriangles = 4096;

// Reorders the triangles of a static mesh with more than `piece_triangles` (>= kMinPieceTriangles)
// so that each run of `piece_triangles` (the last shorter) is a compact piece: halved at the
// centroid median of the longer side, on a multiple of `piece_triangles`, until each part is one
// run. Per-triangle data (triangle_materials) follow their triangles; vertices stay where they
// are. Sets mesh.piece_triangles. A moving mesh or one of at most `piece_triangles` is left alone.
void order_in_pieces(TriangleMesh& mesh, std::uint32_t piece_triangles);

}  // namespace rtpro
