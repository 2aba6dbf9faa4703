#pragma once
// Internals of the OBJ loader (src/scene/obj_loader.cpp). The file is cut into chunks at line
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

// From chunk-local triangle first_triangle on, `usemtl` / `s` state is as given.
struct StateChange {
  std::uint32_t first_triangle;
  std::uint32_t material_slot;  // into Chunk::material_names, or kInherited
  std::uint32_t smoothing;      // a group number, kFlat, or kInherited
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

  // From parse_chunk(); positions and normals go straight to the file-wide arrays. So do the first
  // triangles (as position indices), one slot per `f` line, so a file of triangles needs no copy;
  // the extra triangles of polygons go to more_triangles.
  std::size_t triangles_in_slots = 0;
  std::vector<TriangleIndices> more_triangles;
  std::vector<TriangleIndices> triangle_normals;  // kept only while every corner has a normal
  bool every_corner_has_normal = true;
  std::uint64_t first_zero_normal_line = 0;       // a `vn 0 0 0`; 0: none
  std::vector<StateChange> state_changes;
  std::vector<LocatedName> material_names;        // usemtl, one slot per distinct name
  std::vector<LocatedName> material_libraries;    // mtllib, in order
  LocatedName object_name{};                      // the first `o`
  bool has_smoothing_statement = false;
  std::uint64_t faces = 0;
  std::uint64_t dropped_degenerate = 0;
  std::vector<IgnoredKeyword> ignored;
  std::exception_ptr error;  // an InputError naming file:line:column; parsing stopped there

  std::size_t triangle_count() const { return triangles_in_slots + more_triangles.size(); }
};

// Chunks of about chunk_bytes, each ending just after a newline (the last one at the end).
std::vector<Chunk> split_into_chunks(std::string_view text, std::size_t chunk_bytes);

// Fills chunk.counts. Classifies lines exactly as parse_chunk() does, except that lines too short
// to be valid are not counted: parse_chunk() rejects them, and no input can make the file-wide
// arrays larger than one element per 7 bytes.
void count_chunk(Chunk& chunk);

// Where parse_chunk() writes: slot chunk.start.positions + i for the chunk's i-th `v`, and so on.
struct Destination {
  PaddedVertex* positions;
  Vec3* normals;
  TriangleIndices* triangles;  // chunk.counts.faces slots from chunk.start.faces
  Counts totals;  // of the whole file: positive indices may point forward
  std::string file;
};

void parse_chunk(Chunk& chunk, const Destination& out);

}  // namespace rtpro::obj
