#include "rtpro/scene/mesh.h"

#include "rtpro/scene/motion.h"

namespace rtpro {

BBox TriangleMesh::triangle_bounds(std::uint32_t t) const {
  BBox b;
  const TriangleIndices& tri = triangles[t];
  b.extend(vertex(tri.v0));
  b.extend(vertex(tri.v1));
  b.extend(vertex(tri.v2));
  // Vertices move on straight lines between steps: the steps' boxes hold the whole motion.
  for (const VertexArray& step : vertex_steps)
    for (std::uint32_t v : {tri.v0, tri.v1, tri.v2}) b.extend(step[v].position());
  return b;
}

BBox TriangleMesh::bounds() const {
  BBox b;
  for (const MeshVertex& v : vertices) b.extend(v.position());
  for (const VertexArray& step : vertex_steps)
    for (const MeshVertex& v : step) b.extend(v.position());
  return b;
}

Vec3 TriangleMesh::vertex_at(std::uint32_t i, float time) const {
  const MotionSegment segment = motion_segment(time, vertex_steps.size());
  return motion_lerp(vertex_steps[segment.index][i].position(), vertex_steps[segment.index + 1][i].position(),
                     segment.fraction);
}

Vec3 TriangleMesh::normal_at(std::uint32_t i, float time) const {
  if (normal_steps.empty()) return normal(i);
  const MotionSegment segment = motion_segment(time, normal_steps.size());
  return motion_lerp(normal_steps[segment.index][i], normal_steps[segment.index + 1][i], segment.fraction);
}

void TriangleMesh::pack_normals() {
  if (normals.empty() || !normal_steps.empty()) return;
  packed_normals.resize(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i) packed_normals[i] = encode_octahedral(normals[i]);
  std::vector<Vec3>().swap(normals);
}

std::size_t TriangleMesh::memory_bytes() const {
  return vertices.capacity() * sizeof(MeshVertex) + triangles.capacity() * sizeof(TriangleIndices) +
         normals.capacity() * sizeof(Vec3) + packed_normals.capacity() * sizeof(std::uint32_t) +
         triangle_materials.capacity() * sizeof(std::uint32_t) + uvs.capacity() * sizeof(TexCoord) +
         colors.capacity() * sizeof(Color) + motion_memory_bytes();
}

std::size_t TriangleMesh::motion_memory_bytes() const {
  std::size_t bytes = 0;
  for (const auto& step : vertex_steps) bytes += step.capacity() * sizeof(MeshVertex);
  for (const auto& step : normal_steps) bytes += step.capacity() * sizeof(Vec3);
  return bytes;
}

}  // namespace rtpro
