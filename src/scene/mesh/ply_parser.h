#pragma once
// rtpro's PLY reader, behind load_mesh_file(): ascii, binary_little_endian and binary_big_endian.
//
// - element vertex: x, y, z (any numeric type); nx, ny, nz when all three are present; texture
//   coordinates u, v (or s, t, texture_u, texture_v, texture_s, texture_t); colours red, green,
//   blue (or diffuse_red, ...; integer types scaled to 0..1, then sRGB decoded to linear). Other
//   properties are skipped. element face: a list property vertex_indices (or vertex_index) with
//   integer count and index types; polygons are triangulated as in mesh_triangulation.h (after
//   the triangle faces), triangles with a repeated index or zero area dropped and counted. Other
//   elements are skipped. Unknown header lines are a warning; UTF-16/32 files are refused.
// - Element counts are checked against the bytes after the header before anything is allocated.
// - Errors name file:line:column in ASCII files and the byte offset in binary ones: numbers that
//   are malformed, NaN or infinite, coordinates beyond kMaxAbsCoordinate, indices out of range,
//   faces with fewer than 3 vertices, and a body shorter than the header promises.
// - Normals (options.normals): by default the file's (normalised) when present and non-zero, else
//   none (flat shading, as the format's other readers do); kSmooth generates area-weighted ones,
//   kFlat drops the file's, kFile requires them.
#include "rtpro/scene/mesh_loader.h"

#include <filesystem>

namespace rtpro {

LoadedMesh load_ply_file(const std::filesystem::path& file, const MeshLoadOptions& options = {});

}  // namespace rtpro
