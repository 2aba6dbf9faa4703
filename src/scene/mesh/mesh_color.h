#pragma once
// Vertex colours in files: OBJ and PLY write display values (sRGB-encoded, as viewers show them);
// glTF writes linear ones. TriangleMesh::colors holds linear values, converted on load.
#include <cmath>

namespace rtpro {

inline float srgb_to_linear(float encoded) {
  if (encoded <= 0.04045f) return encoded / 12.92f;
  return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace rtpro
