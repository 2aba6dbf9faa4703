#pragma once
// rtpro's own Wavefront OBJ reader, behind load_mesh_file(). Exposed so tests can force small
// chunks: a parse must give the same arrays whatever the chunk size.
//
// What it reads, and how it decides:
// - v (3 coordinates; a 4th w is validated and ignored, 3 more are an r g b vertex colour), vn,
//   vt (u [v [w]]), f in the forms v, v/vt, v//vn, v/vt/vn. Negative indices count back from the
//   elements declared before their line; positive ones may point forward, up to the file's total.
//   Index 0, out-of-range indices and numbers that are malformed, NaN, infinite or beyond float
//   range are InputErrors naming file:line:column, and so are coordinates beyond
//   kMaxAbsCoordinate. Line continuations ('\') are not supported; a '#' after numbers or indices
//   starts a comment. Files in UTF-16 or UTF-32 are refused; a UTF-8 byte order mark is skipped.
// - Polygons: convex ones become a fan, concave ones are ear-clipped in their plane (a keyhole
//   polygon keeps its hole); see mesh_triangulation.h. Triangles with a repeated position index,
//   and triangles of polygons with zero area, are dropped and counted in stats.dropped_degenerate.
// - Normals (options.normals, NormalsMode::kAuto unless the scene says otherwise): the file's vn
//   when every face corner has one (normalised); when some corner lacks one or a vn has zero
//   length, the file's normals are set aside with a warning. Otherwise by smoothing group, as the
//   specification and Blender, 3ds Max and assimp read it: faces before any `s`, and under `s off`
//   / `s 0`, are flat; faces under `s N` get area-weighted normals shared within group N. Flat
//   triangles in a mesh that also has smooth ones get vertices of their own carrying their face
//   normal; when every face is flat the mesh has no normals at all (the renderer's flat shading).
//   kFlat and kSmooth ignore the file's normals and groups; kFile requires the file's normals.
//   Vertices are split where a position meets different normals, groups or texture coordinates;
//   without splits the file's vertex list is kept as is, unreferenced vertices included.
// - Texture coordinates are kept per vertex (TriangleMesh::uvs) when every face corner has one,
//   vertex colours (TriangleMesh::colors, white where a vertex has none) when any vertex has one.
// - Materials: see obj_materials.h. LoadedMesh::materials lists the materials faces use, in
//   first-use order; faces before any usemtl, or after a `usemtl` without a name (a warning),
//   share one entry named "default". With no usemtl at all the list is empty and mesh.material is
//   kNoMaterial; with one material mesh.material is 0; with more, mesh.triangle_materials holds
//   one index per triangle.
// - o names the mesh (the first one wins; without one the file's stem); g is accepted and unused.
//   Any other statement is ignored with one warning per keyword, for the first 8 keywords, and
//   one line summing up the rest.
#include "rtpro/scene/mesh_loader.h"

#include <cstddef>
#include <filesystem>

namespace rtpro {

// Large enough that per-chunk overhead vanishes, small enough to balance across cores.
inline constexpr std::size_t kDefaultObjChunkBytes = std::size_t(1) << 20;

LoadedMesh load_obj_file(const std::filesystem::path& file, const MeshLoadOptions& options = {},
                         std::size_t chunk_bytes = kDefaultObjChunkBytes);

}  // namespace rtpro
