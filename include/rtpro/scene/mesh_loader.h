#pragma once
// Loading triangle meshes from files (OBJ with MTL, PLY). Every index is bounds-checked and every
// number validated; a malformed file is one InputError naming file:line.
#include "rtpro/scene/description.h"
#include "rtpro/scene/mesh.h"
#include "rtpro/scene/subdivision.h"

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace rtpro {

struct MeshLoadOptions {
  NormalsMode normals = NormalsMode::kAuto;
  // Also keep an OBJ's faces untriangulated (LoadedMesh::cage), for a subdivision surface.
  bool keep_cage = false;
};

struct MeshLoadStats {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t faces = 0;  // polygons read before triangulation
  std::size_t materials = 0;
  std::size_t dropped_degenerate = 0;  // triangles with repeated vertices or zero area, not kept
  std::size_t concave_polygons = 0;    // triangulated by ear clipping instead of a fan
  bool normals_generated = false;
  std::vector<std::string> warnings;  // one line each, already "file:line: ..." formatted
  // Files read besides the mesh file itself (MTL libraries, glTF buffers): a pixel depends on them.
  std::vector<std::filesystem::path> files_read;
};

struct LoadedMesh {
  TriangleMesh mesh;                    // triangle_materials index into `materials` (may be empty)
  std::vector<MaterialDesc> materials;  // from MTL files, in first-use order
  MeshLoadStats stats;
  std::shared_ptr<const PolygonCage> cage;  // with MeshLoadOptions::keep_cage, for an OBJ
};

// Chooses the format by extension (.obj, .ply). Throws InputError for missing or malformed files.
LoadedMesh load_mesh_file(const std::filesystem::path& file, const MeshLoadOptions& options = {});

}  // namespace rtpro
