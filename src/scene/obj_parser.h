#pragma once
// rtpro's own Wavefront OBJ reader, behind load_mesh_file(). Exposed so tests can force small
// chunks: a parse must give the same arrays whatever the chunk size.
//
// What it reads, and how it decides:
// - v (3 coordinates; a 4th w or an r g b colour are validated and ignored), vn, vt (validated,
//   unused), f in the forms v, v/vt, v//vn, v/vt/vn. Negative indices count back from the elements
//   declared before their line; positive ones may point forward, up to the file's total. Index 0,
//   out-of-range indices and numbers that are malformed, NaN, infinite or beyond float range are
//   InputErrors naming file:line:column, and so are coordinates beyond kMaxAbsCoordinate. Line
//   continuations ('\') are not supported; a '#' after numbers or indices starts a comment.
// - Polygons are fan-triangulated (exact for convex ones). A triangle with a repeated position
//   index is dropped and counted in stats.dropped_degenerate.
// - Normals: the file's vn when every face corner has one (normalised); when some corner lacks one
//   or a vn has zero length, the file's normals are set aside with a warning. Otherwise generated as
//   area-weighted smooth normals per smoothing group. A file with no `s` statement at all is
//   treated as one smooth group (scanned models like the Stanford dragon have none and need
//   smooth shading); once any `s` appears, faces before it and under `s off` / `s 0` are flat:
//   each flat triangle gets its own three vertices carrying its face normal. When every face is
//   flat the mesh has no normals at all (the renderer's flat shading).
//   Vertices are split where a position meets different normals or groups; without splits the
//   file's vertex list is kept as is, unreferenced vertices included.
// - Materials: mtllib paths must be relative and stay inside the OBJ's folder (anything else is
//   an InputError); a missing .mtl or an undefined usemtl name is a warning, and that material
//   keeps MaterialDesc's defaults. LoadedMesh::materials lists the materials faces use, in
//   first-use order; faces before any usemtl share one entry named "default". With no usemtl at
//   all the list is empty and mesh.material is kNoMaterial; with one material mesh.material is 0;
//   with more, mesh.triangle_materials holds one index per triangle.
// - o names the mesh (the first one wins; without one the file's stem); g is accepted and unused.
//   Any other statement is ignored with one warning per keyword.
#include "rtpro/scene/mesh_loader.h"

#include <cstddef>
#include <filesystem>

namespace rtpro {

// Large enough that per-chunk overhead vanishes, small enough to balance across cores.
inline constexpr std::size_t kDefaultObjChunkBytes = std::size_t(1) << 20;

LoadedMesh load_obj_file(const std::filesystem::path& file, std::size_t chunk_bytes = kDefaultObjChunkBytes);

}  // namespace rtpro
