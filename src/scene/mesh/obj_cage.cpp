#include "obj_cage.h"

#include <algorithm>

namespace rtpro::obj {

namespace {

// Calls triangle_face(k) for the chunk's k-th triangle face and polygon(p) for its p-th polygon,
// in the order the file wrote them.
template <typename TriangleFace, typename PolygonFace>
void for_each_face_in_order(const Chunk& chunk, TriangleFace&& triangle_face, PolygonFace&& polygon) {
  std::size_t face = 0;
  for (std::size_t p = 0; p < chunk.polygons.size(); ++p) {
    for (; face < chunk.polygons[p].triangles_before; ++face) triangle_face(face);
    polygon(p);
  }
  for (; face < chunk.triangles_in_slots; ++face) triangle_face(face);
}

}  // namespace

PolygonCage gather_cage(const std::vector<Chunk>& chunks, const TriangleIndices* triangle_slots,
                        const VertexArray& positions, const std::vector<TexCoord>* texcoords) {
  PolygonCage cage;
  cage.positions.reserve(positions.size());
  for (const MeshVertex& v : positions) cage.positions.push_back(v.position());
  if (texcoords) cage.uvs = *texcoords;
  for (const Chunk& chunk : chunks) {
    const TriangleIndices* slots = triangle_slots + chunk.start.faces;
    for_each_face_in_order(
        chunk,
        [&](std::size_t k) {
          const TriangleIndices& t = slots[k];
          cage.face_sizes.push_back(3);
          cage.face_vertices.insert(cage.face_vertices.end(), {t.v0, t.v1, t.v2});
          if (!texcoords) return;
          const TriangleIndices& uv = chunk.triangle_texcoords[k];
          cage.face_uvs.insert(cage.face_uvs.end(), {uv.v0, uv.v1, uv.v2});
        },
        [&](std::size_t p) {
          const Polygon& polygon = chunk.polygons[p];
          const Corner* corners = chunk.polygon_corners.data() + polygon.first_corner;
          cage.face_sizes.push_back(polygon.corner_count);
          for (std::uint32_t c = 0; c < polygon.corner_count; ++c) {
            cage.face_vertices.push_back(corners[c].position);
            if (texcoords) cage.face_uvs.push_back(corners[c].texcoord);
          }
        });
  }
  return cage;
}

void assign_cage_materials(PolygonCage& cage, const std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets,
                           const TriangleMesh& mesh) {
  if (mesh.triangle_materials.empty()) return;
  const std::size_t last = mesh.triangle_materials.size() - 1;
  const auto material_of = [&](std::size_t triangle) { return mesh.triangle_materials[std::min(triangle, last)]; };
  cage.face_materials.reserve(cage.face_count());
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    const Chunk& chunk = chunks[c];
    std::size_t from_polygons = 0;  // triangles the chunk's polygons so far became
    for_each_face_in_order(
        chunk, [&](std::size_t k) { cage.face_materials.push_back(material_of(offsets[c] + k + from_polygons)); },
        [&](std::size_t p) {
          cage.face_materials.push_back(material_of(offsets[c] + chunk.polygons[p].triangles_before + from_polygons));
          from_polygons += chunk.triangles_of_polygon[p];
        });
  }
}

}  // namespace rtpro::obj
