#pragma once
// What OpenSubdiv is given: a cage checked for what its refiner cannot take, with the vertices no
// face uses left out and creases and corners renumbered to match.
#include "rtpro/scene/subdivision.h"

#include <cstdint>
#include <string>
#include <vector>

namespace rtpro {

struct CheckedCage {
  PolygonCage cage;  // only the faces kept, only the vertices they use
  std::vector<EdgeCrease> creases;
  std::vector<VertexCorner> corners;
  std::vector<std::uint32_t> source_face;  // per kept face, its index in the file's cage
  std::vector<std::uint32_t> file_vertex;  // per kept vertex, its index in the file's cage
  bool all_quads = true;
  std::vector<std::string> warnings;  // one line each, already naming the file
};

// Faces with fewer than 3 corners or a repeated corner are dropped with a warning. Input errors
// (naming `file` and the face, or the scene entry's crease or corner): an edge shared by more than
// two faces or walked the same way by two faces (a non-manifold or inconsistently wound cage), a
// Loop cage with a face that is not a triangle, a crease between vertices that share no cage edge,
// a corner or crease naming a vertex the file does not have.
CheckedCage check_cage(const PolygonCage& cage, const SubdivisionDesc& desc, const std::string& file);

}  // namespace rtpro
