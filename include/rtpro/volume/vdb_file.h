#pragma once
// OpenVDB files: the one place rtpro reads them (and writes them, for tests and tools). OpenVDB's
// headers stay inside vdb_file.cpp; what leaves it is rtpro's own VoxelGrid.
#include "rtpro/core/error.h"
#include "rtpro/volume/voxel_grid.h"

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rtpro {

// What a volume entry asks of a file: a density grid and, optionally, an emission and a
// temperature grid, each a scalar (float or double) fog volume. `where` is the scene entry that
// names the file: every error is reported there, naming the file and the grid.
struct VdbRequest {
  std::filesystem::path file;
  SourceLocation where;
  std::string density = "density";
  std::string emission;     // empty: none
  std::string temperature;  // empty: none
  // The most the grids may take as rtpro holds them. The estimate the budget was checked against
  // comes from the file's statistics, which a file can misstate: read_vdb_grids counts the bricks
  // of the trees it read against this before filling any.
  std::uint64_t max_bytes = std::numeric_limits<std::uint64_t>::max();
};

// Bytes per active voxel are what the report and `rtpro info` show against the file's own size.
struct VolumeMemory {
  std::uint64_t active_voxels = 0;  // the density grid's
  std::uint64_t bytes = 0;          // every grid read, as rtpro holds it (bricks, tables, majorants)
  std::uint64_t file_bytes = 0;     // the .vdb file
};

struct VdbGrids {
  VoxelGrid density;
  std::optional<VoxelGrid> emission, temperature;
  VolumeMemory memory;
};

// An upper bound on the bytes reading `request` holds at its peak (OpenVDB's tree and rtpro's
// bricks), from the file's grid metadata alone: the budget is checked before any voxel is read.
// Throws InputError for the file and grid errors read_vdb_grids reports that the metadata shows
// (no such file, not a VDB file, no grid of that name, not a scalar grid, no active voxels).
std::uint64_t estimate_vdb_bytes(const VdbRequest& request);

// Reads the grids. Throws InputError, naming the file and grid, for: a missing or unreadable file,
// a missing grid (listing the file's grids), a grid that is not a float or double scalar, a level
// set, a non-linear (frustum) transform, a grid without active voxels, and values that are
// negative, NaN or infinite. Both calls first walk the file's layout as OpenVDB will read it and
// refuse any length, count or offset the file cannot hold (src/volume/vdb_layout_check.h): OpenVDB
// trusts them.
VdbGrids read_vdb_grids(const VdbRequest& request);

// A grid for write_vdb_file: the value type by OpenVDB's name ("float", "double", "int32",
// "vec3s"; a vec3s voxel gets the value on all three components), an index-to-world transform of
// a uniform voxel size and a translation, and active voxels.
struct VdbGridSpec {
  struct Voxel {
    VoxelCoord at;
    float value;
  };
  std::string name;
  std::string type = "float";
  std::vector<Voxel> voxels;
  float background = 0.0f;
  double voxel_size = 1.0;
  std::array<double, 3> translation{0.0, 0.0, 0.0};
  bool level_set = false;  // marks the grid as a level set (its class), as a narrow-band SDF is
  // A tile of active voxels of value `tile_value` from `tile_origin`, as OpenVDB stores constant
  // regions: 8³ voxels in place of a leaf (level 1), 128³ (level 2) or 4096³ (level 3).
  std::optional<VoxelCoord> tile_origin;
  float tile_value = 0.0f;
  int tile_level = 1;
  bool save_as_half = false;  // node values stored as 16-bit halves (float and double grids)
  // No grid class, not a fog volume: OpenVDB compresses fog volumes' and level sets' values with
  // Blosc or not at all, other grids' with zlib too (VdbCompression::kZip).
  bool unclassified = false;
};

// How write_vdb_file compresses node values: OpenVDB's default (Blosc, inactive values left out),
// zlib with the same mask compression, raw but inactive values left out, or raw.
enum class VdbCompression { kBlosc, kZip, kActiveMaskOnly, kNone };

// Writes the grids as openvdb::io::File does (tests and tools).
void write_vdb_file(const std::filesystem::path& file, std::span<const VdbGridSpec> grids,
                    VdbCompression compression = VdbCompression::kBlosc);

}  // namespace rtpro
