#pragma once
// An OBJ's faces kept as the file wrote them, the cage a subdivision surface refines (see
// scene/subdivision.h), gathered from the parsed chunks beside the triangulated mesh.
#include "obj_chunk.h"
#include "rtpro/scene/subdivision.h"

#include <cstddef>
#include <vector>

namespace rtpro::obj {

// Every face in file order: triangle faces from their slots, polygons from their corners, so it
// runs before triangulate_polygons() frees those. `texcoords`: the file's vt lines when every
// corner has one, else null (the cage then has no uvs).
PolygonCage gather_cage(const std::vector<Chunk>& chunks, const TriangleIndices* triangle_slots,
                        const VertexArray& positions, const std::vector<TexCoord>* texcoords);

// Each face's material: that of the first triangle its face became in `mesh` (`offsets`: the
// chunks' first triangles), once the polygons are triangulated.
void assign_cage_materials(PolygonCage& cage, const std::vector<Chunk>& chunks, const std::vector<std::size_t>& offsets,
                           const TriangleMesh& mesh);

}  // namespace rtpro::obj
