#pragma once
// Internals of the OBJ loader: turning the stitched file-wide arrays into a TriangleMesh's
// vertices, triangles and normals (see obj_parser.h for the rules).
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"

#include <cstdint>
#include <vector>

namespace rtpro::obj {

// From triangle first_triangle on (until the next run), faces use this material and smoothing.
struct TriangleRun {
  std::uint32_t first_triangle;
  std::uint32_t material;   // index into the loaded material list
  std::uint32_t smoothing;  // a group number, or kFlat
};

struct MeshParts {
  VertexArray positions;            // the file's v lines, in order
  std::vector<Vec3> normals;        // the file's vn lines, in order
  std::vector<TexCoord> texcoords;  // the file's vt lines, in order
  std::vector<Color> colors;        // per position, or empty
  std::vector<TriangleIndices> triangle_positions;
  std::vector<TriangleIndices> triangle_normals;    // per triangle when the file's normals are used
  std::vector<TriangleIndices> triangle_texcoords;  // per triangle when texture coordinates are kept
  std::vector<TriangleRun> runs;                    // in order, the first at triangle 0
};

// Fills mesh.vertices, triangles, normals, uvs and colors. Returns whether normals were generated;
// `repaired_normals` counts the file's normals that were zero or not finite (repair_vertex_normals).
bool assemble_mesh(MeshParts parts, TriangleMesh& mesh, std::size_t& repaired_normals);

}  // namespace rtpro::obj
