// The walk in front of OpenVDB's reader (src/volume/vdb_layout_check.cpp), through the calls that
// use it: files OpenVDB writes in every compression read as written; files with one length,
// count or offset changed are refused, naming the byte and the field, before OpenVDB trusts it.
#include "rtpro/volume/vdb_file.h"

#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace rtpro {
namespace vdb_layout_check_test {

VdbGridSpec density_grid() {
  VdbGridSpec spec;
  spec.name = "density";
  spec.voxel_size = 0.5;
  spec.translation = {1.0, 2.0, 3.0};
  spec.voxels = {{{0, 0, 0}, 1.0f}, {{1, 0, 0}, 3.0f}, {{-9, 4, 20}, 0.25f}};
  return spec;
}

// One leaf full of a constant: a block Blosc compresses.
VdbGridSpec full_leaf_grid() {
  VdbGridSpec spec = density_grid();
  spec.voxels.clear();
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y)
      for (int z = 0; z < 8; ++z) spec.voxels.push_back({{x, y, z}, 0.5f});
  return spec;
}

VdbRequest request_for(const std::filesystem::path& file) {
  VdbRequest request;
  request.file = file;
  request.where = SourceLocation{"scene.yaml", 3, 9};
  return request;
}

std::string read_error(const std::filesystem::path& file) {
  return test::error_message_of<InputError>([&] { read_vdb_grids(request_for(file)); });
}

// A file OpenVDB wrote, its bytes to change, and where its fields are.
class WrittenFile {
 public:
  WrittenFile(const std::string& name, const VdbGridSpec& grid, VdbCompression compression = VdbCompression::kBlosc)
      : path_(test::write_file(name, "")) {
    write_vdb_file(path_, std::span<const VdbGridSpec>(&grid, 1), compression);
    bytes_ = test::read_file(path_);
  }

  std::uint64_t size() const { return bytes_.size(); }
  const std::filesystem::path& path() const { return path_; }
  std::size_t find(const std::string& text) const {
    const std::size_t at = bytes_.find(text);
    EXPECT_NE(at, std::string::npos) << text;
    return at;
  }
  // The first grid's offsets: its start, its data blocks, its end (after the descriptor's type
  // name and empty instance parent).
  std::int64_t offset(int which) const {
    const std::string type = "Tree_float_5_4_3";
    return value<std::int64_t>(find(type) + type.size() + 4 + 8 * static_cast<std::size_t>(which));
  }
  template <typename T>
  T value(std::size_t at) const {
    T v;
    std::memcpy(&v, bytes_.data() + at, sizeof(T));
    return v;
  }
  template <typename T>
  const std::filesystem::path& with(std::size_t at, T v) {
    std::memcpy(bytes_.data() + at, &v, sizeof(T));
    test::write_file(path_.filename().string(), bytes_);
    return path_;
  }

 private:
  std::filesystem::path path_;
  std::string bytes_;
};

// The uncompressed values of a leaf, or the Blosc block of them: after the leaf's value mask in the
// data blocks, its value flag, then the chunk's size.
constexpr std::size_t kFirstLeafChunk = 64 + 1;

TEST(VdbLayoutCheck, EveryCompressionAndHalfFloatsReadAsWritten) {
  for (const VdbCompression compression :
       {VdbCompression::kBlosc, VdbCompression::kZip, VdbCompression::kActiveMaskOnly, VdbCompression::kNone})
    for (const char* type : {"float", "double"})
      for (const bool half : {false, true}) {
        VdbGridSpec spec = density_grid();
        spec.type = type;
        spec.save_as_half = half;
        spec.unclassified = compression == VdbCompression::kZip;  // zlib compresses no fog volume
        spec.tile_origin = VoxelCoord{16, 0, 0};
        spec.tile_value = 0.5f;
        VdbGridSpec full = full_leaf_grid();
        // 64 leaves more: OpenVDB compresses the delayed-load tables of so many leaves (and pads
        // a short one to 128 bytes).
        for (int i = 1; i <= 64; ++i) full.voxels.push_back({{8 * i, 0, 0}, 0.25f});
        full.name = "full";
        full.type = type;
        full.save_as_half = half;
        full.unclassified = spec.unclassified;
        const std::filesystem::path file = test::scratch_dir() / "every.vdb";
        const std::vector<VdbGridSpec> grids{spec, full};
        write_vdb_file(file, grids, compression);
        SCOPED_TRACE(std::string(type) + (half ? " as halves" : "") + ", compression " +
                     std::to_string(static_cast<int>(compression)));
        const VdbGrids read = read_vdb_grids(request_for(file));
        EXPECT_EQ(read.density.voxel(1, 0, 0), 3.0f);  // exact in a half too
        EXPECT_EQ(read.density.voxel(-9, 4, 20), 0.25f);
        EXPECT_EQ(read.density.voxel(23, 7, 7), 0.5f);
        EXPECT_EQ(read.density.active_voxels, 3u + 512u);
        VdbRequest second = request_for(file);
        second.density = "full";
        EXPECT_EQ(read_vdb_grids(second).density.voxel(7, 7, 7), 0.5f);
      }
}

TEST(VdbLayoutCheck, AMetadataStringLongerThanTheFileIsRefusedBeforeOpenVdbFillsIt) {
  // Found by mutating the shipped smoke.vdb: OpenVDB filled 4 GB strings for 47 s and 19 GB.
  WrittenFile file("long-string.vdb", density_grid());
  const std::size_t size_at = file.find("blosc + active values") - 4;
  const std::string message = read_error(file.with<std::uint32_t>(size_at, 0xffffffffu));
  EXPECT_NE(message.find("scene.yaml:3:9"), std::string::npos) << message;
  EXPECT_NE(message.find("long-string.vdb: not a readable OpenVDB file (at byte " + std::to_string(size_at + 4) +
                         ", metadata 'file_compression' of the grid 'density' needs 4294967295 bytes"),
            std::string::npos)
      << message;
  EXPECT_EQ(test::error_message_of<InputError>(
                [&] { estimate_vdb_bytes(request_for(file.with<std::uint32_t>(size_at, 0xffffffffu))); }),
            message);
}

TEST(VdbLayoutCheck, AFileChangedAfterItsLayoutWasFoundGoodIsWalkedAgain) {
  // A good file's walk is remembered for the read that follows its estimate, as it was then.
  WrittenFile file("changed.vdb", density_grid());
  const std::filesystem::file_time_type written = std::filesystem::last_write_time(file.path());
  EXPECT_GT(estimate_vdb_bytes(request_for(file.path())), 0u);
  const std::size_t size_at = file.find("blosc + active values") - 4;
  file.with<std::uint32_t>(size_at, 0xffffffffu);  // the same size, other bytes
  std::filesystem::last_write_time(file.path(), written + std::chrono::seconds(1));
  EXPECT_NE(read_error(file.path()).find("metadata 'file_compression' of the grid 'density' needs 4294967295 bytes"),
            std::string::npos);
}

TEST(VdbLayoutCheck, CountsTheFileCannotHoldAreRefused) {
  {
    // The root's tile count: OpenVDB loops over it reading past the end of the file (a hang).
    WrittenFile file("tiles.vdb", density_grid());
    const std::string map = "UniformScaleTranslateMap";
    const std::size_t tiles_at = file.find(map) + map.size() + 6 * 24 + 4 + 4;
    ASSERT_EQ(file.value<std::uint32_t>(tiles_at), 0u);
    const std::string message = read_error(file.with<std::uint32_t>(tiles_at, 0xffffffffu));
    EXPECT_NE(message.find("the root of the grid 'density' counts 4294967295 tiles and 2 children"), std::string::npos)
        << message;
  }
  {
    // A root child whose origin is not one the root keys by: OpenVDB's corners would overflow.
    WrittenFile file("origin.vdb", density_grid());
    const std::string map = "UniformScaleTranslateMap";
    const std::size_t first_child_at = file.find(map) + map.size() + 6 * 24 + 4 + 4 + 8;
    ASSERT_EQ(file.value<std::int32_t>(first_child_at), -4096);
    const std::string message = read_error(file.with<std::int32_t>(first_child_at, 2147483647));
    EXPECT_NE(message.find("the origin of a root child of the grid 'density' is not a multiple of 4096"),
              std::string::npos)
        << message;
  }
  {
    WrittenFile file("metadata-count.vdb", density_grid());
    const std::size_t count_at = file.find("class") - 8;  // the grid's metadata count, then 'class'
    ASSERT_GT(file.value<std::uint32_t>(count_at), 5u);
    const std::string message = read_error(file.with<std::uint32_t>(count_at, 1u << 30));
    EXPECT_NE(message.find("the grid 'density' counts 1073741824 metadata items"), std::string::npos) << message;
  }
}

TEST(VdbLayoutCheck, BoolsOfNeitherZeroNorOneAreRefused) {
  // OpenVDB reads the byte into a bool: any other value is undefined behaviour where it is used.
  WrittenFile file("bool.vdb", density_grid());
  const std::string name = "is_saved_as_half_float";
  const std::size_t value_at = file.find(name) + name.size() + 4 + 4 + 4;  // type "bool", its size
  ASSERT_EQ(file.value<std::uint8_t>(value_at), 0u);
  const std::string message = read_error(file.with<std::uint8_t>(value_at, 99));
  EXPECT_NE(message.find("at byte " + std::to_string(value_at) + ", metadata 'is_saved_as_half_float' of the grid " +
                         "'density' is a bool of neither 0 nor 1"),
            std::string::npos)
      << message;
}

TEST(VdbLayoutCheck, WhetherValuesAreHalvesIsReadFromTheGridsMetadataAsOpenVdbReadsIt) {
  // OpenVDB takes it from the grid's is_saved_as_half_float, not from the descriptor's type name
  // (a fuzz finding: a flag of an unknown type read as true sent OpenVDB past the file's end).
  VdbGridSpec spec = density_grid();
  spec.save_as_half = true;
  const std::string name = "is_saved_as_half_float";
  {
    WrittenFile file("flag.vdb", spec);
    const std::size_t value_at = file.find(name) + name.size() + 4 + 4 + 4;
    ASSERT_EQ(file.value<std::uint8_t>(value_at), 1u);
    // Read as floats, the halves' chunks are half the size OpenVDB would expect.
    const std::string message = read_error(file.with<std::uint8_t>(value_at, 0));
    EXPECT_NE(message.find("flag.vdb: not a readable OpenVDB file"), std::string::npos) << message;
  }
  WrittenFile file("type.vdb", spec);
  const std::size_t type_at = file.find(name) + name.size() + 4;
  const std::string message = read_error(file.with<char>(type_at + 1, 'g'));  // "bgol"
  EXPECT_NE(message.find("metadata 'is_saved_as_half_float' of the grid 'density' is a bgol, not a bool"),
            std::string::npos)
      << message;
}

TEST(VdbLayoutCheck, GridOffsetsOutsideTheFileAreRefused) {
  WrittenFile file("offsets.vdb", density_grid());
  const std::size_t end_at = file.find("Tree_float_5_4_3") + 16 + 4 + 16;
  ASSERT_EQ(file.offset(2), static_cast<std::int64_t>(file.size()));
  const std::string message = read_error(file.with<std::int64_t>(end_at, file.offset(2) + 1));
  EXPECT_NE(message.find("the grid 'density' is placed at bytes"), std::string::npos) << message;
}

TEST(VdbLayoutCheck, RawValuesLargerThanTheirNodeAreRefusedBeforeOpenVdbReadsThemIntoIt) {
  // OpenVDB 10 reads a raw chunk's stated size into the node's buffer before comparing it with the
  // buffer (a fuzz finding: heap corruption). zlib does not shrink one voxel's value: it is raw.
  VdbGridSpec grid = density_grid();
  grid.unclassified = true;  // zlib compresses no fog volume
  WrittenFile file("raw.vdb", grid, VdbCompression::kZip);
  const std::size_t chunk_at = static_cast<std::size_t>(file.offset(1)) + kFirstLeafChunk;
  ASSERT_EQ(file.value<std::int64_t>(chunk_at), -4);
  const std::string message = read_error(file.with<std::int64_t>(chunk_at, -4096));
  EXPECT_NE(message.find("the values of a leaf of the grid 'density' states -4096 raw bytes for 4 bytes of values"),
            std::string::npos)
      << message;
}

TEST(VdbLayoutCheck, ABloscBlockStatingMoreThanItsChunkIsRefused) {
  // Blosc reads the size its own header states, whatever the chunk OpenVDB read holds.
  WrittenFile file("blosc.vdb", full_leaf_grid());
  const std::size_t chunk_at = static_cast<std::size_t>(file.offset(1)) + kFirstLeafChunk;
  const auto chunk = file.value<std::int64_t>(chunk_at);
  ASSERT_GT(chunk, 16);
  const std::size_t block_bytes_at = chunk_at + 8 + 12;
  ASSERT_LE(file.value<std::uint32_t>(block_bytes_at), static_cast<std::uint64_t>(chunk));
  const std::string message =
      read_error(file.with<std::uint32_t>(block_bytes_at, static_cast<std::uint32_t>(chunk) + 4096));
  EXPECT_NE(message.find("the values of a leaf of the grid 'density' is a Blosc block of"), std::string::npos)
      << message;
}

TEST(VdbLayoutCheck, AFileThatIsNotOpenVdbOrCutShortIsRefusedNamingTheField) {
  EXPECT_NE(read_error(test::write_file("short.vdb", "BDV"))
                .find("short.vdb: not a readable OpenVDB file (at byte 0, "
                      "OpenVDB's magic number needs 8 bytes"),
            std::string::npos);
  const std::string bytes = test::read_file(WrittenFile("cut.vdb", density_grid()).path());
  const std::string message = read_error(test::write_file("cut.vdb", bytes.substr(0, bytes.size() - 100)));
  EXPECT_NE(message.find("cut.vdb: not a readable OpenVDB file (at byte"), std::string::npos) << message;
  EXPECT_NE(message.find("the grid 'density' is placed at bytes"), std::string::npos) << message;
}

}  // namespace vdb_layout_check_test
}  // namespace rtpro
