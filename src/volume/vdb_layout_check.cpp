#include "vdb_layout_check.h"

#include "rtpro/core/printable_text.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <span>
#include <string_view>
#include <system_error>
#include <vector>

namespace rtpro {

namespace {

// OpenVDB's magic number, "BDV " as a little-endian int64.
constexpr std::uint64_t kMagic = 0x56444220;
// OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION: from this format on each grid states its own
// compression and the file header holds none; OpenVDB 10 writes 224 (MULTIPASS_IO).
constexpr std::uint32_t kOldestFormat = 222;
constexpr std::uint32_t kNewestFormat = 224;
constexpr std::size_t kUuidChars = 36;  // boost::uuids as text, which OpenVDB reads with >>
// The smallest metadata item: a name's length, a type's length, a value's size.
constexpr std::uint64_t kMetadataItemBytes = 12;
// The smallest grid descriptor: three lengths (name, type, instance parent) and three offsets.
constexpr std::uint64_t kDescriptorBytes = 3 * 4 + 3 * 8;
// A root node's child: its origin, then an internal node of 32³ entries, whose child and value
// masks (4096 bytes each) and compression flag come first.
constexpr std::uint64_t kRootChildBytes = 12 + 2 * 4096 + 1;
// io::COMPRESS_* flags, as each grid states them.
constexpr std::uint32_t kCompressZip = 0x1, kCompressActiveMask = 0x2, kCompressBlosc = 0x4;
// io::readCompressedValues' per-node flags that add inactive values or a selection mask.
constexpr std::uint8_t kNoMaskAndOneInactiveVal = 2, kMaskAndNoInactiveVals = 3, kMaskAndOneInactiveVal = 4,
                       kMaskAndTwoInactiveVals = 5, kNoMaskAndAllVals = 6;
constexpr std::uint64_t kBloscHeaderBytes = 16;
constexpr std::uint32_t kBloscPadBytes = 128;  // points/StreamCompression.h: BLOSC_PAD_BYTES
// The 5-4-3 tree: internal nodes of 32³ and 16³ entries above leaves of 8³ voxels.
constexpr int kUpperLog2 = 5, kLowerLog2 = 4;
constexpr std::uint32_t kLeafVoxels = 512;
constexpr std::int32_t kRootChildVoxels = 4096;  // a root child's side: 32 × 16 × 8
constexpr std::size_t kLeafMaskBytes = kLeafVoxels / 8;

// Value sizes OpenVDB reads for its registered fixed-size metadata types, whatever size the file
// states for them (TypedMetadata::readValue): a stated size that differs puts OpenVDB's reading
// of the rest out of step with this walk, so it is refused.
std::optional<std::uint32_t> metadata_fixed_size(std::string_view type) {
  static const std::map<std::string_view, std::uint32_t, std::less<>> kSizes = {
      {"bool", 1},    {"double", 8},  {"float", 4},   {"int32", 4},       {"int64", 8},
      {"vec2i", 8},   {"vec2s", 8},   {"vec2d", 16},  {"vec3i", 12},      {"vec3s", 12},
      {"vec3d", 24},  {"vec4i", 16},  {"vec4s", 16},  {"vec4d", 32},      {"mat4s", 64},
      {"mat4d", 128}, {"ptidx32", 4}, {"ptidx64", 8}, {"ptdataidx32", 4}, {"ptdataidx64", 8}};
  const auto found = kSizes.find(type);
  return found == kSizes.end() ? std::nullopt : std::optional<std::uint32_t>(found->second);
}

// The bytes each registered linear map reads (math/Maps.h: Mat4d = 128, Vec3d = 24).
std::optional<std::uint64_t> linear_map_bytes(std::string_view type) {
  static const std::map<std::string_view, std::uint64_t, std::less<>> kSizes = {{"AffineMap", 128},
                                                                                {"UnitaryMap", 128},
                                                                                {"ScaleMap", 5 * 24},
                                                                                {"UniformScaleMap", 5 * 24},
                                                                                {"TranslationMap", 24},
                                                                                {"ScaleTranslateMap", 6 * 24},
                                                                                {"UniformScaleTranslateMap", 6 * 24}};
  const auto found = kSizes.find(type);
  return found == kSizes.end() ? std::nullopt : std::optional<std::uint64_t>(found->second);
}

// A scalar tree rtpro reads (Tree_float_5_4_3, Tree_double_5_4_3), as the grid stores it.
struct TreeLayout {
  std::uint64_t value_bytes = 4;  // a value as the tree holds it (backgrounds, tiles, inactive values)
  bool half = false;              // node values stored as 16-bit halves (the grid's is_saved_as_half_float)
  std::uint32_t compression = 0;  // the grid's io::COMPRESS_* flags
};

// The descriptor's type name, without the _HalfFloat suffix it carries when the grid was saved
// as halves.
std::optional<TreeLayout> scalar_tree(std::string_view type) {
  constexpr std::string_view kHalf = "_HalfFloat";
  TreeLayout tree;
  if (type.ends_with(kHalf)) type.remove_suffix(kHalf.size());
  if (type == "Tree_float_5_4_3") return tree;
  if (type == "Tree_double_5_4_3") {
    tree.value_bytes = 8;
    return tree;
  }
  return std::nullopt;
}

struct LayoutError {
  std::string message;
};

// The file read at explicit offsets through a window of it, every read checked against the end
// of the section it belongs to (a grid's metadata and topology lie before its data blocks, its
// blocks before its end).
class LayoutWalk {
 public:
  LayoutWalk(const std::filesystem::path& file, std::uint64_t size) : in_(file, std::ios::binary), size_(size) {}

  bool opened() const { return static_cast<bool>(in_); }
  std::uint64_t size() const { return size_; }
  std::uint64_t at() const { return at_; }
  void seek(std::uint64_t at) { at_ = at; }
  // The section the next reads must stay in ends at `end` (at most the file's end).
  void limit(std::uint64_t end) { end_ = std::min(end, size_); }
  std::uint64_t left() const { return at_ < end_ ? end_ - at_ : 0; }

  [[noreturn]] void fail(const std::string& what) const {
    throw LayoutError{"at byte " + std::to_string(at_) + ", " + what};
  }
  void need(std::uint64_t bytes, const std::string& what) const {
    if (bytes > left())
      fail(what + " needs " + std::to_string(bytes) + " bytes, more than the " + std::to_string(left()) + " left" +
           (end_ < size_ ? " in its section" : " in the file"));
  }
  void skip(std::uint64_t bytes, const std::string& what) {
    need(bytes, what);
    at_ += bytes;
  }
  std::uint8_t u8(const std::string& what) {
    std::uint8_t b = 0;
    read(&b, 1, what);
    return b;
  }
  std::uint32_t u32(const std::string& what) {
    unsigned char b[4];
    read(b, 4, what);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
  }
  std::uint64_t u64(const std::string& what) {
    need(8, what);
    const std::uint64_t low = u32(what);
    return low | std::uint64_t(u32(what)) << 32;
  }
  std::int64_t i64(const std::string& what) { return static_cast<std::int64_t>(u64(what)); }
  // A length-prefixed string (OpenVDB's readString); its first 200 bytes are kept for messages
  // and type names, the rest skipped.
  std::string string(const std::string& what) {
    const std::uint32_t length = u32(what);
    need(length, what + " of " + std::to_string(length) + " bytes");
    std::string text(std::min<std::uint32_t>(length, 200), '\0');
    read(text.data(), text.size(), what);
    at_ += length - text.size();
    return text;
  }
  void read(void* into, std::size_t bytes, const std::string& what) {
    need(bytes, what);
    auto* out = static_cast<unsigned char*>(into);
    while (bytes > 0) {
      if (at_ < window_at_ || at_ >= window_at_ + window_.size()) fill();
      const std::size_t offset = at_ - window_at_;
      const std::size_t count = std::min(bytes, window_.size() - offset);
      std::copy_n(window_.data() + offset, count, out);
      out += count;
      at_ += count;
      bytes -= count;
    }
  }

 private:
  // The window from the current position: a tree's nodes are read in small pieces between skips.
  void fill() {
    window_.resize(static_cast<std::size_t>(std::min<std::uint64_t>(kWindowBytes, size_ - at_)));
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(at_));
    if (!in_.read(reinterpret_cast<char*>(window_.data()), static_cast<std::streamsize>(window_.size()))) {
      window_.clear();
      fail("the file could not be read");
    }
    window_at_ = at_;
  }

  static constexpr std::uint64_t kWindowBytes = 1 << 16;
  std::ifstream in_;
  std::uint64_t size_ = 0, at_ = 0, end_ = 0;
  std::vector<unsigned char> window_;
  std::uint64_t window_at_ = 0;
};

std::string in_quotes(const std::string& name) { return "'" + printable_text(name, 64) + "'"; }

void check_header(LayoutWalk& walk) {
  walk.limit(walk.size());
  if (walk.u64("OpenVDB's magic number") != kMagic) {
    walk.seek(0);
    walk.fail("not OpenVDB's magic number");
  }
  const std::uint32_t format = walk.u32("the format version");
  if (format < kOldestFormat || format > kNewestFormat)
    walk.fail("format version " + std::to_string(format) + "; OpenVDB 10 files are of versions " +
              std::to_string(kOldestFormat) + " to " + std::to_string(kNewestFormat));
  walk.skip(8, "the library version");
  unsigned char has_offsets = 0;
  walk.read(&has_offsets, 1, "the grid-offsets flag");
  // Without offsets OpenVDB reads every grid whole as it opens the file (an io::Stream archive).
  if (has_offsets == 0) walk.fail("a stream archive without grid offsets; rtpro reads files openvdb::io::File writes");
  char uuid[kUuidChars];
  walk.read(uuid, kUuidChars, "the file's UUID");
  for (std::size_t i = 0; i < kUuidChars; ++i) {
    const char c = uuid[i];
    const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
    if (dash ? c != '-' : !std::isxdigit(static_cast<unsigned char>(c))) {
      walk.seek(walk.at() - kUuidChars + i);
      walk.fail("the file's UUID is not 36 characters of hexadecimal digits and dashes");
    }
  }
}

// OpenVDB reads a bool's byte straight into a bool: any other value than 0 or 1 is undefined
// behaviour where it is used (UBSan: "load of value 99, which is not a valid value for type
// 'bool'", a fuzz finding in a root tile).
bool check_bool(LayoutWalk& walk, const std::string& what) {
  const std::uint8_t value = walk.u8(what);
  if (value > 1) {
    walk.seek(walk.at() - 1);
    walk.fail(what + " is a bool of neither 0 nor 1");
  }
  return value == 1;
}

// io::DelayedLoadMetadata::readValue: a leaf count, then a mask of that many bytes and a table of
// that many 8-byte sizes, each raw or as a Blosc block that declares its size uncompressed.
void check_delayed_load(LayoutWalk& walk, std::uint32_t stated, const std::string& what) {
  if (stated == 0) return;
  const std::uint64_t start = walk.at();
  // Each leaf whose table this is takes more than a byte of the file.
  const std::uint32_t count = walk.u32(what + "'s leaf count");
  if (count > walk.size()) walk.fail(what + " counts " + std::to_string(count) + " leaves in a file of fewer bytes");
  const auto table = [&](std::uint64_t element, const std::string& part) {
    const std::uint32_t compressed = walk.u32(what + "'s " + part + " size");
    if (compressed == 0) return walk.skip(std::uint64_t{count} * element, what + "'s " + part);
    // A Blosc block's header: its version bytes, then its uncompressed and compressed sizes.
    if (compressed < kBloscHeaderBytes)
      walk.fail(what + "'s " + part + " is a compressed block of " + std::to_string(compressed) +
                " bytes, shorter than a Blosc header");
    const std::uint64_t block = walk.at();
    walk.skip(4, what + "'s " + part);
    const std::uint32_t uncompressed = walk.u32(what + "'s " + part);
    walk.skip(4, what + "'s " + part);
    const std::uint32_t stated_compressed = walk.u32(what + "'s " + part);
    // What compression::bloscDecompress accepts: the table's bytes, or OpenVDB's padding of a
    // shorter table to 128 bytes.
    const std::uint64_t expected = std::uint64_t{count} * element;
    const bool padded = uncompressed == kBloscPadBytes && expected <= kBloscPadBytes;
    if ((uncompressed != expected && !padded) || stated_compressed > compressed)
      walk.fail(what + "'s " + part + " declares " + std::to_string(uncompressed) + " bytes uncompressed for " +
                std::to_string(count) + " leaves");
    walk.seek(block);
    walk.skip(compressed, what + "'s " + part);
  };
  table(1, "mask");
  // The size table is absent when its length reads 0xffffffff.
  const std::uint64_t sizes_at = walk.at();
  if (walk.u32(what + "'s size table") != 0xffffffffu) {
    walk.seek(sizes_at);
    table(8, "size table");
  }
  const std::uint64_t used = walk.at() - start;
  if (used > stated) walk.fail(what + " states " + std::to_string(stated) + " bytes but holds " + std::to_string(used));
  walk.seek(start);
  walk.skip(stated, what);  // OpenVDB skips what it does not know at the end
}

// GridBase::META_SAVE_HALF_FLOAT: a grid's values are read as halves when this metadata says so,
// whatever the descriptor's type name says (the grid's metadata replaces what the descriptor set).
constexpr std::string_view kSavedAsHalf = "is_saved_as_half_float";

// MetaMap::readMeta: a count, then each item's name, type name, stated size and value.
// `saved_as_half`, for a grid: set to the last is_saved_as_half_float item's value, false without one.
void check_metadata(LayoutWalk& walk, const std::string& owner, bool* saved_as_half = nullptr) {
  if (saved_as_half) *saved_as_half = false;
  const std::uint32_t count = walk.u32("the metadata count of " + owner);
  if (count > walk.left() / kMetadataItemBytes)
    walk.fail(owner + " counts " + std::to_string(count) + " metadata items, more than its " +
              std::to_string(walk.left()) + " bytes can hold");
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::string name = walk.string("the name of metadata item " + std::to_string(i + 1) + " of " + owner);
    const std::string what = "metadata " + in_quotes(name) + " of " + owner;
    const std::string type = walk.string("the type of " + what);
    const std::uint32_t stated = walk.u32("the size of " + what);
    // Any other type would need its own idea of truth (GridBase::saveFloatAsHalf asks asBool()).
    if (saved_as_half && name == kSavedAsHalf) {
      if (type != "bool" || stated != 1) walk.fail(what + " is a " + printable_text(type, 64) + ", not a bool");
      *saved_as_half = check_bool(walk, what);
      continue;
    }
    if (type == "__delayedload") {
      check_delayed_load(walk, stated, what);
    } else if (const std::optional<std::uint32_t> fixed = metadata_fixed_size(type)) {
      if (stated != *fixed)
        walk.fail(what + " states " + std::to_string(stated) + " bytes for a " + printable_text(type) + " of " +
                  std::to_string(*fixed));
      if (type == "bool") check_bool(walk, what);
      else walk.skip(stated, what);
    } else {
      walk.skip(stated, what);  // a string, or a type OpenVDB keeps as raw bytes
    }
  }
}

// Transform::read: the map's type name, then the map; a frustum holds a second, linear map.
void check_transform(LayoutWalk& walk, const std::string& owner) {
  const std::string type = walk.string("the transform type of " + owner);
  if (type == "NonlinearFrustumMap") {
    walk.skip(6 * 8 + 2 * 8, "the frustum of " + owner);  // its box, taper and depth
    const std::string second = walk.string("the frustum's second map type of " + owner);
    const std::optional<std::uint64_t> bytes = linear_map_bytes(second);
    if (!bytes) walk.fail("the frustum of " + owner + " holds a map of type " + in_quotes(second));
    return walk.skip(*bytes, "the frustum's second map of " + owner);
  }
  const std::optional<std::uint64_t> bytes = linear_map_bytes(type);
  if (!bytes)
    walk.fail("the transform of " + owner + " is of type " + in_quotes(type) + ", which OpenVDB 10 does not read");
  walk.skip(*bytes, "the transform of " + owner);
}

// What the messages call a kind of node's fields, made once per grid: a tree's walk reads
// these fields for every node, and builds a message only when one is wrong.
struct NodeLabels {
  explicit NodeLabels(const std::string& node)
      : flag("the value flag of " + node), inactive("the inactive values of " + node),
        selection("the selection mask of " + node), values("the values of " + node),
        size("the size of the values of " + node), child_mask("the child mask of " + node),
        value_mask("the value mask of " + node) {}
  std::string flag, inactive, selection, values, size, child_mask, value_mask;
};

// io::bloscFromStream and io::unzipFromStream read an int64 first. A negative one is the size of
// the raw values that follow: both read that many bytes into the node's buffer before comparing it
// with the buffer's size, so a larger one overruns the heap (OpenVDB 10; a fuzz finding: glibc's
// "free(): invalid size"). A positive one is the compressed size; Blosc then reads its own header
// and as many bytes as that states, whatever the buffer holds.
void check_chunk(LayoutWalk& walk, const TreeLayout& tree, std::uint64_t bytes, const NodeLabels& labels) {
  const std::string& what = labels.values;
  if (!(tree.compression & (kCompressBlosc | kCompressZip))) return walk.skip(bytes, what);
  const std::int64_t stated = walk.i64(labels.size);
  if (stated <= 0) {
    if (stated == std::numeric_limits<std::int64_t>::min() || static_cast<std::uint64_t>(-stated) != bytes)
      walk.fail(what + " states " + std::to_string(stated) + " raw bytes for " + std::to_string(bytes) +
                " bytes of values");
    return walk.skip(bytes, what);
  }
  const auto compressed = static_cast<std::uint64_t>(stated);
  walk.need(compressed, what);
  if (tree.compression & kCompressBlosc) {
    if (compressed < kBloscHeaderBytes)
      walk.fail(what + " is a Blosc block of " + std::to_string(compressed) + " bytes, shorter than its header");
    const std::uint64_t block = walk.at();
    walk.skip(4, what);
    const std::uint32_t uncompressed = walk.u32(what);
    walk.skip(4, what);
    const std::uint32_t block_bytes = walk.u32(what);
    if (uncompressed != bytes || block_bytes > compressed)
      walk.fail(what + " is a Blosc block of " + std::to_string(block_bytes) + " bytes declaring " +
                std::to_string(uncompressed) + " uncompressed, in " + std::to_string(compressed) + " bytes for " +
                std::to_string(bytes) + " bytes of values");
    walk.seek(block);
  }
  walk.skip(compressed, what);
}

// One node's values as io::readCompressedValues reads them: a flag, up to two inactive values and
// a selection mask, then the values (all `total`, or the `active` ones under mask compression).
void check_node_values(LayoutWalk& walk, const TreeLayout& tree, std::uint32_t total, std::uint32_t active,
                       const NodeLabels& labels) {
  const std::uint8_t flag = walk.u8(labels.flag);
  if (flag == kNoMaskAndOneInactiveVal || flag == kMaskAndOneInactiveVal || flag == kMaskAndTwoInactiveVals)
    walk.skip(tree.value_bytes * (flag == kMaskAndTwoInactiveVals ? 2 : 1), labels.inactive);
  if (flag == kMaskAndNoInactiveVals || flag == kMaskAndOneInactiveVal || flag == kMaskAndTwoInactiveVals)
    walk.skip(total / 8, labels.selection);
  const std::uint64_t count = (tree.compression & kCompressActiveMask) && flag != kNoMaskAndAllVals ? active : total;
  if (tree.half && count == 0) return;  // HalfReader reads nothing then
  check_chunk(walk, tree, count * (tree.half ? 2 : tree.value_bytes), labels);
}

std::uint32_t bits_on(std::span<const unsigned char> mask) {
  std::uint32_t on = 0;
  for (const unsigned char byte : mask) on += static_cast<std::uint32_t>(std::popcount(byte));
  return on;
}

// The topology below the root, as InternalNode::readTopology reads it: child and value masks, the
// node's values, then each child in the order of its bit. A leaf's topology is its value mask;
// the number of its active voxels is kept, in reading order, for its buffer.
struct TreeLabels {
  explicit TreeLabels(const std::string& owner)
      : internal("an internal node of " + owner), leaf("a leaf of " + owner) {}
  NodeLabels internal, leaf;
};

void check_internal_topology(LayoutWalk& walk, const TreeLayout& tree, int log2_dim, const TreeLabels& labels,
                             std::vector<std::uint16_t>& leaf_active) {
  const std::uint32_t entries = 1u << (3 * log2_dim);
  std::vector<unsigned char> child_mask(entries / 8), value_mask(entries / 8);
  walk.read(child_mask.data(), child_mask.size(), labels.internal.child_mask);
  walk.read(value_mask.data(), value_mask.size(), labels.internal.value_mask);
  check_node_values(walk, tree, entries, bits_on(value_mask), labels.internal);
  unsigned char leaf_mask[kLeafMaskBytes];
  for (std::size_t byte = 0; byte < child_mask.size(); ++byte)
    for (int bit = 0; bit < 8; ++bit) {
      if (!(child_mask[byte] >> bit & 1)) continue;
      if (log2_dim == kUpperLog2) {
        check_internal_topology(walk, tree, kLowerLog2, labels, leaf_active);
      } else {
        walk.read(leaf_mask, kLeafMaskBytes, labels.leaf.value_mask);
        leaf_active.push_back(static_cast<std::uint16_t>(bits_on(leaf_mask)));
      }
    }
}

// Tree::readTopology and readBuffers: a buffer count, the root (background, tiles, children),
// the topology below it, then each leaf's buffer (a value mask OpenVDB skips, then its values,
// read with the active count of the leaf's mask in the topology). OpenVDB reads the buffers in
// the order of the root's table, a std::map by origin, so children must come in that order, each
// origin once (real files do: they are written from that map).
void check_tree(LayoutWalk& walk, const TreeLayout& tree, const std::string& owner, std::uint64_t end) {
  walk.skip(4, "the buffer count of " + owner);
  walk.skip(tree.value_bytes, "the background of " + owner);
  const std::uint32_t tiles = walk.u32("the root's tile count of " + owner);
  const std::uint32_t children = walk.u32("the root's child count of " + owner);
  const std::uint64_t needed =
      std::uint64_t{tiles} * (12 + tree.value_bytes + 1) + std::uint64_t{children} * kRootChildBytes;
  if (needed > walk.left())
    walk.fail("the root of " + owner + " counts " + std::to_string(tiles) + " tiles and " + std::to_string(children) +
              " children, which need " + std::to_string(needed) + " bytes; " + std::to_string(walk.left()) +
              " are left before its data blocks");
  using Origin = std::array<std::int32_t, 3>;
  // The root keys its entries by their first voxel, a multiple of a child's 4096 voxels: so
  // OpenVDB's corner arithmetic (origin + 4095) cannot overflow.
  const auto origin = [&](const std::string& what) {
    const Origin at{static_cast<std::int32_t>(walk.u32(what)), static_cast<std::int32_t>(walk.u32(what)),
                    static_cast<std::int32_t>(walk.u32(what))};
    for (const std::int32_t c : at)
      if (c % kRootChildVoxels != 0) walk.fail(what + " is not a multiple of " + std::to_string(kRootChildVoxels));
    return at;
  };
  std::vector<Origin> tile_origins;
  for (std::uint32_t i = 0; i < tiles; ++i) {
    tile_origins.push_back(origin("the origin of a root tile of " + owner));
    walk.skip(tree.value_bytes, "a root tile of " + owner);
    check_bool(walk, "whether a root tile of " + owner + " is active");
  }
  std::sort(tile_origins.begin(), tile_origins.end());
  const TreeLabels labels(owner);
  std::vector<std::uint16_t> leaf_active;
  std::optional<Origin> previous;
  for (std::uint32_t i = 0; i < children; ++i) {
    const Origin at = origin("the origin of a root child of " + owner);
    if ((previous && !(*previous < at)) || std::binary_search(tile_origins.begin(), tile_origins.end(), at))
      walk.fail("the root of " + owner + " holds a child at an origin not after the previous child's, or at a tile's");
    previous = at;
    check_internal_topology(walk, tree, kUpperLog2, labels, leaf_active);
  }
  walk.limit(end);
  for (const std::uint16_t active : leaf_active) {
    walk.skip(kLeafMaskBytes, labels.leaf.value_mask);
    check_node_values(walk, tree, kLeafVoxels, active, labels.leaf);
  }
}

struct GridPlace {
  std::string name, type;
  bool instance = false;
  std::uint64_t grid = 0, blocks = 0, end = 0;
};

// GridDescriptor::read: names, type, instance parent and three offsets, then io::File seeks to
// the descriptor's end for the next one.
std::vector<GridPlace> check_descriptors(LayoutWalk& walk) {
  const std::uint32_t raw_count = walk.u32("the grid count");
  const auto count = static_cast<std::int32_t>(raw_count);
  if (count < 0 || static_cast<std::uint64_t>(count) > walk.left() / kDescriptorBytes)
    walk.fail("the file counts " + std::to_string(count) + " grids, more than its " + std::to_string(walk.left()) +
              " bytes left can describe");
  std::vector<GridPlace> grids;
  for (std::int32_t i = 0; i < count; ++i) {
    GridPlace place;
    const std::string which = "grid " + std::to_string(i + 1);
    place.name = walk.string("the name of " + which);
    const std::string owner = "the grid " + in_quotes(place.name);
    place.type = walk.string("the type of " + owner);
    place.instance = !walk.string("the instance parent of " + owner).empty();
    const std::uint64_t descriptor_end = walk.at() + 24;
    const std::int64_t grid = walk.i64("the offsets of " + owner);
    const std::int64_t blocks = walk.i64("the offsets of " + owner);
    const std::int64_t end = walk.i64("the offsets of " + owner);
    if (grid < static_cast<std::int64_t>(descriptor_end) || blocks < grid || end < blocks ||
        static_cast<std::uint64_t>(end) > walk.size())
      walk.fail(owner + " is placed at bytes " + std::to_string(grid) + ", " + std::to_string(blocks) + " and " +
                std::to_string(end) + ", not in order within the file's " + std::to_string(walk.size()) + " bytes");
    place.grid = static_cast<std::uint64_t>(grid);
    place.blocks = static_cast<std::uint64_t>(blocks);
    place.end = static_cast<std::uint64_t>(end);
    grids.push_back(place);
    walk.seek(place.end);
  }
  return grids;
}

// io::File::readGridPartial and Archive::readGrid: compression, metadata and transform before the
// grid's data blocks, then, for the scalar trees rtpro reads, the tree up to the grid's end.
void check_grid(LayoutWalk& walk, const GridPlace& place) {
  const std::string owner = "the grid " + in_quotes(place.name);
  walk.seek(place.grid);
  walk.limit(place.blocks);
  const std::uint32_t compression = walk.u32("the compression of " + owner);
  bool saved_as_half = false;
  check_metadata(walk, owner, &saved_as_half);
  check_transform(walk, owner);
  if (std::optional<TreeLayout> tree = scalar_tree(place.type); tree && !place.instance) {
    tree->compression = compression;
    tree->half = saved_as_half;
    check_tree(walk, *tree, owner, place.end);
  }
}

}  // namespace

std::optional<std::string> vdb_layout_problem(const std::filesystem::path& file) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return "its size could not be read (" + error.message() + ")";
  LayoutWalk walk(file, size);
  if (!walk.opened()) return std::string("it could not be opened");
  try {
    check_header(walk);
    check_metadata(walk, "the file");
    for (const GridPlace& place : check_descriptors(walk)) check_grid(walk, place);
  } catch (const LayoutError& e) {
    return e.message;
  }
  return std::nullopt;
}

}  // namespace rtpro
