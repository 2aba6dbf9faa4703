// The OpenVDB half of vdb_file.h, built into librtpro_vdb.so (vdb_plugin.cpp): the only source
// that calls OpenVDB.
#include "openvdb_file.h"

#include "vdb_layout_check.h"

#include "rtpro/core/closest_match.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/core/printable_text.h"

// OpenVDB's headers are heavy (Boost, TBB, Imath); no other file of rtpro includes them.
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <system_error>

namespace rtpro {

namespace {

void initialize_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

// "smoke.vdb: grid 'density'": how every message names what it is about.
std::string grid_label(const VdbRequest& request, const std::string& grid) {
  return printable_text(request.file.string()) + ": grid '" + printable_text(grid) + "'";
}

[[noreturn]] void fail(const VdbRequest& request, const std::string& message) {
  throw InputError(request.where, message);
}

// vdb_layout_problem, remembering the last file found good as it was then (size and modification
// time): a volume entry's estimate and its read open the same file one after the other, and a
// large file's walk reads most of it.
std::optional<std::string> layout_problem(const std::filesystem::path& file) {
  struct Seen {
    std::filesystem::path file;
    std::uintmax_t size = 0;
    std::filesystem::file_time_type::rep modified = 0;
    bool operator==(const Seen&) const = default;
  };
  static std::mutex mutex;
  static std::optional<Seen> last_good;
  std::error_code size_error, time_error;
  const Seen now{file, std::filesystem::file_size(file, size_error),
                 std::filesystem::last_write_time(file, time_error).time_since_epoch().count()};
  const bool known = !size_error && !time_error;
  if (known) {
    const std::lock_guard lock(mutex);
    if (last_good == now) return std::nullopt;
  }
  std::optional<std::string> problem = vdb_layout_problem(file);
  if (!problem && known) {
    const std::lock_guard lock(mutex);
    last_good = now;
  }
  return problem;
}

// The open file, its grids' metadata (no voxels), and what the request names.
class VdbSource {
 public:
  explicit VdbSource(const VdbRequest& request) : request_(request), file_(request.file.string()) {
    initialize_openvdb();
    std::error_code error;
    if (!std::filesystem::is_regular_file(request.file, error))
      fail(request, printable_text(request.file.string()) + ": no such OpenVDB file");
    // Before OpenVDB reads a byte: it trusts every length and count the file states.
    if (const std::optional<std::string> problem = layout_problem(request.file))
      fail(request, printable_text(request.file.string()) + ": not a readable OpenVDB file (" + *problem + ")");
    try {
      file_.open(/*delayLoad=*/false);
      grids_ = file_.readAllGridMetadata();
    } catch (const std::exception& e) {
      fail(request, printable_text(request.file.string()) + ": not a readable OpenVDB file (" + e.what() + ")");
    }
  }
  VdbSource(const VdbSource&) = delete;
  VdbSource& operator=(const VdbSource&) = delete;
  ~VdbSource() {
    if (file_.isOpen()) file_.close();
  }

  // The grid's metadata and transform, checked to be one rtpro can render; `role` says what it is
  // for ("density", "emission", "temperature").
  openvdb::GridBase::ConstPtr metadata(const std::string& name, const std::string& role) const {
    for (const openvdb::GridBase::Ptr& grid : *grids_) {
      if (grid->getName() != name) continue;
      const std::string type = grid->valueType();
      if (type != "float" && type != "double")
        fail(request_, grid_label(request_, name) + " holds " + type + " values; a " + role +
                           " grid must hold float (or double) scalars");
      if (grid->getGridClass() == openvdb::GRID_LEVEL_SET)
        fail(request_, grid_label(request_, name) +
                           " is a level set (a signed distance), not a density; convert it to a fog volume first "
                           "(openvdb::tools::sdfToFogVolume, Houdini's Convert VDB)");
      if (!grid->transform().isLinear())
        fail(request_, grid_label(request_, name) + " has a frustum (non-linear) transform, which rtpro does not read");
      return grid;
    }
    std::vector<std::string> names, listed;
    for (const openvdb::GridBase::Ptr& grid : *grids_) {
      names.push_back(grid->getName());
      listed.push_back(printable_text(grid->getName()) + " (" + grid->valueType() + ")");
    }
    std::string list;
    for (const std::string& entry : listed) list += (list.empty() ? "" : ", ") + entry;
    fail(request_, printable_text(request_.file.string()) + " has no grid named '" + printable_text(name) + "'" +
                       (names.empty() ? std::string("; it holds no grids") : "; its grids: " + list) +
                       suggestion(name, names));
  }

  openvdb::GridBase::Ptr read(const std::string& name) {
    try {
      return file_.readGrid(name);
    } catch (const std::exception& e) {
      fail(request_, grid_label(request_, name) + " could not be read (" + e.what() + ")");
    }
  }

 private:
  const VdbRequest& request_;
  openvdb::io::File file_;
  openvdb::GridPtrVecPtr grids_;
};

// The grids a request names, density first, with the role each plays.
std::vector<std::pair<std::string, std::string>> requested_grids(const VdbRequest& request) {
  std::vector<std::pair<std::string, std::string>> grids{{request.density, "density"}};
  if (!request.emission.empty()) grids.emplace_back(request.emission, "emission");
  if (!request.temperature.empty()) grids.emplace_back(request.temperature, "temperature");
  return grids;
}

template <typename T>
std::optional<T> meta_value(const openvdb::GridBase& grid, const char* key) {
  if (const auto meta = grid.getMetadata<openvdb::TypedMetadata<T>>(key)) return meta->value();
  return std::nullopt;
}

VoxelBox voxel_box(const openvdb::CoordBBox& box) {
  if (box.empty()) return {};
  return {{box.min().x(), box.min().y(), box.min().z()}, {box.max().x(), box.max().y(), box.max().z()}};
}

// From the statistics OpenVDB writes beside every grid (file_voxel_count, file_bbox_*,
// file_mem_bytes): at most one brick per active voxel and per brick of the box, plus the table.
std::optional<std::uint64_t> estimated_grid_bytes(const openvdb::GridBase& grid) {
  const auto voxels = meta_value<openvdb::Int64>(grid, openvdb::GridBase::META_FILE_VOXEL_COUNT);
  const auto lo = meta_value<openvdb::Vec3i>(grid, openvdb::GridBase::META_FILE_BBOX_MIN);
  const auto hi = meta_value<openvdb::Vec3i>(grid, openvdb::GridBase::META_FILE_BBOX_MAX);
  const auto tree_bytes = meta_value<openvdb::Int64>(grid, openvdb::GridBase::META_FILE_MEM_BYTES);
  if (!voxels || !lo || !hi || !tree_bytes || *voxels < 0 || *tree_bytes < 0) return std::nullopt;
  const VoxelBox box{{(*lo)[0], (*lo)[1], (*lo)[2]}, {(*hi)[0], (*hi)[1], (*hi)[2]}};
  const std::uint64_t bricks = std::min(static_cast<std::uint64_t>(*voxels), VoxelGrid::table_entries(box));
  return saturating_add(static_cast<std::uint64_t>(*tree_bytes), VoxelGrid::bytes_for(box, bricks));
}

// The bricks the tree fills: one per leaf, and one per 8³ voxels of each active tile.
template <typename GridType>
std::uint64_t bricks_of(const GridType& grid) {
  std::uint64_t bricks = grid.tree().leafCount();
  auto tile = grid.tree().cbeginValueOn();
  tile.setMaxDepth(grid.tree().treeDepth() - 2);  // above the leaves: tiles, not voxels
  for (; tile; ++tile) bricks = saturating_add(bricks, tile.getBoundingBox().volume() / VoxelGrid::kBrickVoxels);
  return bricks;
}

// Copies a scalar grid's leaves and active tiles into bricks, refusing values a density (or an
// emission or temperature) cannot have.
template <typename GridType>
VoxelGrid to_voxel_grid(const GridType& grid, const VdbRequest& request, std::uint64_t bricks) {
  const std::string& name = grid.getName();
  const float background = static_cast<float>(grid.background());
  if (!std::isfinite(background) || background < 0.0f)
    fail(request, grid_label(request, name) + " has a background of " + std::to_string(background) +
                      "; values must be finite and not negative");
  VoxelGrid voxels(voxel_box(grid.evalActiveVoxelBoundingBox()), background);
  voxels.reserve_bricks(bricks);

  std::uint64_t bad = 0;
  std::optional<std::pair<openvdb::Coord, float>> first_bad;
  auto check = [&](const openvdb::Coord& at, float value) {
    if (std::isfinite(value) && value >= 0.0f) return;
    if (bad++ == 0) first_bad.emplace(at, value);
  };
  for (auto leaf = grid.tree().cbeginLeaf(); leaf; ++leaf) {
    if (leaf->isEmpty()) continue;  // no active voxel: lookups there read the background
    const openvdb::Coord origin = leaf->origin();
    const std::span<float> brick = voxels.brick_at({origin.x(), origin.y(), origin.z()});
    for (openvdb::Index i = 0; i < VoxelGrid::kBrickVoxels; ++i) {
      const float value = static_cast<float>(leaf->getValue(i));
      brick[i] = value;
      check(leaf->offsetToGlobalCoord(i), value);
    }
  }
  auto tile = grid.tree().cbeginValueOn();
  tile.setMaxDepth(grid.tree().treeDepth() - 2);  // above the leaves: tiles, not voxels
  for (; tile; ++tile) {
    const float value = static_cast<float>(*tile);
    const openvdb::CoordBBox box = tile.getBoundingBox();
    check(box.min(), value);
    voxels.fill(voxel_box(box), value);
  }
  if (bad > 0) {
    const auto& [at, value] = *first_bad;
    fail(request, grid_label(request, name) + " has " + std::to_string(bad) +
                      (bad == 1 ? " voxel that is" : " voxels that are") + " negative or not finite (the first: " +
                      std::to_string(value) + " at [" + std::to_string(at.x()) + ", " + std::to_string(at.y()) + ", " +
                      std::to_string(at.z()) + "]); values must be finite and not negative");
  }
  voxels.seal();

  // OpenVDB's maps act on row vectors: world = [i j k 1] × M.
  const openvdb::math::Mat4d m = grid.transform().baseMap()->getAffineMap()->getMat4();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) voxels.index_to_medium.m[r][c] = static_cast<float>(m(c, r));
    voxels.index_to_medium.m[r][3] = static_cast<float>(m(3, r));
  }
  return voxels;
}

// `taken`: what the request's grids read before this one hold.
VoxelGrid read_scalar_grid(VdbSource& source, const VdbRequest& request, const std::string& name,
                           const std::string& role, std::uint64_t taken) {
  source.metadata(name, role);
  const openvdb::GridBase::Ptr grid = source.read(name);
  const openvdb::Index64 active = grid->activeVoxelCount();
  if (active == 0) fail(request, grid_label(request, name) + " has no active voxels");
  const auto floats = openvdb::GridBase::grid<openvdb::FloatGrid>(grid);
  const auto doubles = openvdb::GridBase::grid<openvdb::DoubleGrid>(grid);
  // The tree, not the statistics the budget was checked against: a 10 KB file whose statistics
  // claimed one voxel held a tile of 4096³ (10 GB and rising after a minute, unchecked).
  const VoxelBox box = voxel_box(grid->evalActiveVoxelBoundingBox());
  const std::uint64_t bricks = floats ? bricks_of(*floats) : bricks_of(*doubles);
  const std::uint64_t bytes = VoxelGrid::bytes_for(box, bricks);
  if (saturating_add(taken, bytes) > request.max_bytes)
    fail(request,
         grid_label(request, name) + " holds " + std::to_string(active) + " active voxels, " + format_bytes(bytes) +
             " as rtpro holds them, more than the " +
             format_bytes(request.max_bytes - std::min(taken, request.max_bytes)) + " left of the memory budget" +
             (estimated_grid_bytes(*grid).value_or(bytes) < bytes ? " (the file's statistics claim less)" : "") +
             "; raise the budget with --max-memory MiB");
  VoxelGrid voxels = floats ? to_voxel_grid(*floats, request, bricks) : to_voxel_grid(*doubles, request, bricks);
  voxels.active_voxels = active;
  return voxels;
}

}  // namespace

std::uint64_t openvdb_estimate_bytes(const VdbRequest& request) {
  VdbSource source(request);
  std::uint64_t total = 0;
  for (const auto& [name, role] : requested_grids(request)) {
    const openvdb::GridBase::ConstPtr grid = source.metadata(name, role);
    if (meta_value<openvdb::Int64>(*grid, openvdb::GridBase::META_FILE_VOXEL_COUNT) == openvdb::Int64{0})
      fail(request, grid_label(request, name) + " has no active voxels");
    // A file written without statistics is measured when it is read.
    total = saturating_add(total, estimated_grid_bytes(*grid).value_or(0));
  }
  return total;
}

VdbGrids openvdb_read_grids(const VdbRequest& request) {
  VdbSource source(request);
  VdbGrids grids;
  grids.density = read_scalar_grid(source, request, request.density, "density", 0);
  std::uint64_t taken = grids.density.memory_bytes();
  if (!request.emission.empty()) {
    grids.emission = read_scalar_grid(source, request, request.emission, "emission", taken);
    taken = saturating_add(taken, grids.emission->memory_bytes());
  }
  if (!request.temperature.empty())
    grids.temperature = read_scalar_grid(source, request, request.temperature, "temperature", taken);

  grids.memory.active_voxels = grids.density.active_voxels;
  grids.memory.bytes = grids.density.memory_bytes() + (grids.emission ? grids.emission->memory_bytes() : 0) +
                       (grids.temperature ? grids.temperature->memory_bytes() : 0);
  std::error_code error;
  grids.memory.file_bytes = std::filesystem::file_size(request.file, error);
  if (error) grids.memory.file_bytes = 0;
  return grids;
}

namespace {

template <typename GridType, typename Convert>
openvdb::GridBase::Ptr make_grid(const VdbGridSpec& spec, Convert convert) {
  const auto grid = GridType::create(convert(spec.background));
  auto access = grid->getAccessor();
  for (const VdbGridSpec::Voxel& voxel : spec.voxels)
    access.setValueOn(openvdb::Coord(voxel.at[0], voxel.at[1], voxel.at[2]), convert(voxel.value));
  if (spec.tile_origin) {
    const VoxelCoord& o = *spec.tile_origin;
    grid->tree().addTile(static_cast<openvdb::Index>(spec.tile_level), openvdb::Coord(o[0], o[1], o[2]),
                         convert(spec.tile_value), true);
  }
  return grid;
}

}  // namespace

void openvdb_write_file(const std::filesystem::path& file, std::span<const VdbGridSpec> grids,
                        VdbCompression compression) {
  initialize_openvdb();
  openvdb::GridPtrVec out;
  for (const VdbGridSpec& spec : grids) {
    openvdb::GridBase::Ptr grid;
    if (spec.type == "float") grid = make_grid<openvdb::FloatGrid>(spec, [](float v) { return v; });
    else if (spec.type == "double") grid = make_grid<openvdb::DoubleGrid>(spec, [](float v) { return double{v}; });
    else if (spec.type == "int32")
      grid = make_grid<openvdb::Int32Grid>(spec, [](float v) { return static_cast<openvdb::Int32>(v); });
    else if (spec.type == "vec3s")
      grid = make_grid<openvdb::Vec3SGrid>(spec, [](float v) { return openvdb::Vec3s(v, v, v); });
    else throw InputError("write_vdb_file: unknown grid type '" + spec.type + "'");
    grid->setName(spec.name);
    grid->setGridClass(spec.level_set      ? openvdb::GRID_LEVEL_SET
                       : spec.unclassified ? openvdb::GRID_UNKNOWN
                                           : openvdb::GRID_FOG_VOLUME);
    openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(spec.voxel_size);
    transform->postTranslate(openvdb::Vec3d(spec.translation[0], spec.translation[1], spec.translation[2]));
    grid->setTransform(transform);
    grid->setSaveFloatAsHalf(spec.save_as_half);
    out.push_back(grid);
  }
  openvdb::io::File writer(file.string());
  switch (compression) {
    case VdbCompression::kBlosc: break;  // OpenVDB's default
    case VdbCompression::kZip:
      writer.setCompression(openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_ACTIVE_MASK);
      break;
    case VdbCompression::kActiveMaskOnly: writer.setCompression(openvdb::io::COMPRESS_ACTIVE_MASK); break;
    case VdbCompression::kNone: writer.setCompression(openvdb::io::COMPRESS_NONE); break;
  }
  writer.write(out);
}

}  // namespace rtpro
