#pragma once
// rtpro's PLY reader, behind load_mesh_file(): ascii, binary_little_endian and binary_big_endian.
//
// - element vertex: x, y, z (any numeric type), and nx, ny, nz when all three are present;
//   other properties are skipped. element face: a list property vertex_indices (or vertex_index)
//   with integer count and index types; polygons are fan-triangulated, triangles with a repeated
//   index dropped and counted. Other elements are skipped.
// - Element counts are checked against the bytes after the header before anything is allocated.
// - Errors name file:line:column in ASCII files and the byte offset in binary ones: numbers that
//   are malformed, NaN or infinite, coordinates beyond kMaxAbsCoordinate, indices out of range,
//   faces with fewer than 3 vertices, and a body shorter than the header promises.
// - Normals: the file's (normalised) when present and non-zero, else area-weighted smooth normals.
#include "rtpro/scene/mesh_loader.h"

#include <filesystem>

namespace rtpro {

LoadedMesh load_ply_file(const std::filesystem::path& file);

}  // namespace rtpro
