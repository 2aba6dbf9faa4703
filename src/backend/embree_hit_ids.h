#pragma once
// Where the ids of the Embree top scene differ from rtpro's, and how a hit gets rtpro's back, so
// that nothing after the backend knows: the pieces of large top-level meshes (embree_pieces.h),
// and the shapes of instances that place their prototype as is (Instance::places_as_is), attached
// to the top scene itself so that rays need not enter an instance to reach them. A hit on one of
// those is reported as the instance's (its id, the shape's id in the prototype), as Embree would
// have reported it through the instance: with the identity, the ray and so the hit are the same.
#include "embree_pieces.h"
#include "rtpro/backend/hit.h"

#include <cstdint>
#include <vector>

namespace rtpro {

struct EmbreeInlinedShape {
  std::uint32_t instance;  // the instance's id in the top group
  std::uint32_t geometry;  // the shape's id in the instance's prototype
};

struct EmbreeHitIds {
  EmbreePieces pieces;
  std::uint32_t first_inlined = 0;  // top-scene id of the first inlined shape; the others follow it
  std::vector<EmbreeInlinedShape> inlined;

  void resolve(Hit& hit) const {
    pieces.resolve(hit);
    if (hit.inst_id != kInvalidId) return;
    // Unsigned: the ids of the top group and of the pieces, below first_inlined, wrap past the table.
    const std::uint32_t shape = hit.geom_id - first_inlined;
    if (shape >= inlined.size()) return;
    hit.inst_id = inlined[shape].instance;
    hit.geom_id = inlined[shape].geometry;
  }
};

}  // namespace rtpro
