#pragma once
// Large top-level meshes built in pieces (scene/mesh_pieces.h): each piece an Embree scene of its
// own, so that Embree's build holds one piece's primitive records at a time, placed in the top
// scene by an instance without a transform. Embree reports a hit in a piece as the instance's;
// resolve() gives it back as the mesh's own (its geometry, its triangle number, no instance), so
// that nothing after the backend knows pieces exist.
#include "rtpro/backend/hit.h"

#include <cstdint>
#include <vector>

namespace rtpro {

struct EmbreePiece {
  std::uint32_t geometry;        // the mesh's id in the top group
  std::uint32_t first_triangle;  // the piece's first triangle in the mesh
};

struct EmbreePieces {
  std::uint32_t first_instance = 0;  // top-scene id of piece 0's instance; the others follow it
  std::vector<EmbreePiece> pieces;

  void resolve(Hit& hit) const {
    // Unsigned: ids below first_instance, and kInvalidId, wrap past the table.
    const std::uint32_t piece = hit.inst_id - first_instance;
    if (piece >= pieces.size()) return;
    hit.geom_id = pieces[piece].geometry;
    hit.prim_id += pieces[piece].first_triangle;
    hit.inst_id = kInvalidId;
  }
};

}  // namespace rtpro
