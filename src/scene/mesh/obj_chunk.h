#pragma once
// Internals of the OBJ loader (src/scene/mesh/obj_parser.cpp). The file is cut into chunks at line
// boundaries; every chunk is first counted, then parsed, in parallel. A chunk's parse needs only
// the counts of the chunks before it (to resolve relative indices and name lines), and the loader
// stitches chunks together in file order, so the result does not depend on the chunk size.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/mesh.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

namespace rtpro::obj {

struct Counts {
  std::uint64_t lines = 0;
  std::uint64_t positions = 0;  // v
  std::uint64_t normals = 0;    // vn
  std::uint64_t texcoords = 0;  // vt
  std::uint64_t faces = 0;      // f
  Counts& operator+=(const Counts& o) {
    lines += o.lines;
    positions += o.positions;
    normals += o.normals;
    texcoords += o.texcoords;
    faces += o.faces;
    return *this;
  }
};

inline constexpr std::uint32_t kInherited = ~0u;  // a state this chunk has not set (yet)
inline constexpr std::uint32_t kFlat = 0;         // smoothing group of `s off` and `s 0`

// From chunk-local triangle first_triangle on, `usemtl` / `s` state is as given. Polygons are
// triangulated after the parse: first_triangle counts the triangle faces before the change, and
// polygons_before says how many polygons (whose triangles come later) precede it.
struct StateChange {
  std::uint32_t first_triangle;
  std::uint32_t polygons_before;
  std::uint32_t material_slot;  // into Chunk::material_names, or kInherited
  std::uint32_t smoothing;      // a group number, kFlat, or kInherited
};

inline constexpr std::uint32_t kNoIndex = ~0u;

// One face vertex: its position index and, when given, texture coordinate and normal indices.
struct Corner {
  std::uint32_t position;
  std::uint32_t texcoord;  // kNoIndex without one
  std::uint32_t normal;    // kNoIndex without one
};

// A face of more than 3 vertices, triangulated once every position is known.
struct Polygon {
  std::uint32_t triangles_before;  // chunk-local triangles (of triangle faces) read before it
  std::uint32_t first_corner;      // into Chunk::polygon_corners
  std::uint32_t corner_count;
  std::uint64_t line;
};

// A `v x y z r g b` colour, for the position with this file-wide index.
struct VertexColor {
  std::uint32_t position;
  Color color;
};

// A name from the file with the (global, 1-based) line it appeared on.
struct LocatedName {
  std::string_view name;
  std::uint64_t line;
};

struct IgnoredKeyword {
  std::string_view keyword;
  std::uint64_t count;
  std::uint64_t first_line;
};

struct Chunk {
  std::string_view text;
  Counts counts;  // this chunk's own, from count_chunk()
  Counts start;   // the sum over all earlier chunks

  // From parse_chunk(); positions, normals and texture coordinates go straight to the file-wide
  // arrays. So do triangle faces (as position indices), one slot per `f` line, so a file of
  // triangles needs no copy. Polygons wait in `polygons` for every position to be known.
  std::size_t triangles_in_slots = 0;
  std::vector<TriangleIndices> triangle_normals;    // kept only while every corner has a normal
  std::vector<TriangleIndices> triangle_texcoords;  // kept only while every corner has one
  bool every_corner_has_normal = true;
  bool every_corner_has_texcoord = true;
  std::uint64_t first_zero_normal_line = 0;  // a `vn 0 0 0`; 0: none
  std::vector<Polygon> polygons;
  std::vector<Corner> polygon_corners;
  std::vector<VertexColor> colors;
  std::vector<StateChange> state_changes;
  std::vector<LocatedName> material_names;      // usemtl, one slot per distinct name
  std::vector<LocatedName> material_libraries;  // mtllib, in order
  LocatedName object_name{};                    // the first `o`
  std::uint64_t first_unnamed_usemtl_line = 0;  // `usemtl` without a name; 0: none
  bool has_smoothing_statement = false;
  std::uint64_t faces = 0;
  std::uint64_t dropped_degenerate = 0;
  std::vector<IgnoredKeyword> ignored;  // one entry per distinct keyword
  std::exception_ptr error;             // an InputError naming file:line:column; parsing stopped there

  // After triangulate_polygons(): the polygons' triangles in order, with their attribute indices
  // (kept only while the chunk's triangle faces keep theirs), and how many each polygon gave.
  std::vector<TriangleIndices> polygon_triangles;
  std::vector<TriangleIndices> polygon_triangle_normals;
  std::vector<TriangleIndices> polygon_triangle_texcoords;
  std::vector<std::uint32_t> triangles_of_polygon;
  std::uint64_t concave_polygons = 0;
  std::uint64_t fan_fallback_line = 0;  // the first concave polygon that could not be ear-clipped

  std::size_t triangle_count() const { return triangles_in_slots + polygon_triangles.size(); }
};

// Chunks of about chunk_bytes, each ending just after a newline (the last one at the end).
std::vector<Chunk> split_into_chunks(std::string_view text, std::size_t chunk_bytes);

// Fills chunk.counts. Classifies lines exactly as parse_chunk() does, except that lines too short
// to be valid are not counted: parse_chunk() rejects them, and no input can make the file-wide
// arrays larger than one element per 7 bytes.
void count_chunk(Chunk& chunk);

// Where parse_chunk() writes: slot chunk.start.positions + i for the chunk's i-th `v`, and so on.
struct Destination {
  MeshVertex* positions;
  Vec3* normals;
  TexCoord* texcoords;
  TriangleIndices* triangles;  // chunk.counts.faces slots from chunk.start.faces
  Counts totals;               // of the whole file: positive indices may point forward
  std::string file;
};

void parse_chunk(Chunk& chunk, const Destination& out);

// Triangulates the chunk's polygons (convex: a fan; concave: ear clipping) once `positions` holds
// every vertex of the file. Triangles with a repeated position or zero area are dropped and counted.
void triangulate_polygons(Chunk& chunk, const VertexArray& positions);

}  // namespace rtpro::obj
