#include "rtpro/scene/mesh.h"

namespace rtpro {

BBox TriangleMesh::triangle_bounds(std::uint32_t t) const {
  BBox b;
  const TriangleIndices& tri = triangles[t];
  b.extend(vertex(tri.v0));
  b.extend(vertex(tri.v1));
  b.extend(vertex(tri.v2));
  return b;
}

BBox TriangleMesh::bounds() const {
  BBox b;
  for (const PaddedVertex& v : vertices) b.extend(v.position());
  return b;
}

std::size_t TriangleMesh::memory_bytes() const {
  return vertices.capacity() * sizeof(PaddedVertex) + triangles.capacity() * sizeof(TriangleIndices) +
         normals.capacity() * sizeof(Vec3) + triangle_materials.capacity() * sizeof(std::uint32_t) +
         uvs.capacity() * sizeof(TexCoord) + colors.capacity() * sizeof(Color);
}

}  // namespace rtpro
