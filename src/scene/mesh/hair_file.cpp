#include "hair_file.h"

#include "mapped_file.h"
#include "mesh_limits.h"
#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"

#include <cmath>
#include <cstring>
#include <string>

namespace rtpro {

namespace {

constexpr std::size_t kHeaderBytes = 128;
enum HairArrays : std::uint32_t { kSegments = 1, kPoints = 2, kThickness = 4, kTransparency = 8, kColor = 16 };

struct HairHeader {
  char magic[4];
  std::uint32_t strands, points, arrays, default_segments;
  float default_thickness, default_transparency, default_color[3];
  char info[88];
};
static_assert(sizeof(HairHeader) == kHeaderBytes);

template <typename T>
T read_at(const char* bytes, std::size_t index) {
  T value;
  std::memcpy(&value, bytes + index * sizeof(T), sizeof(T));
  return value;
}

class HairReader {
 public:
  explicit HairReader(const std::filesystem::path& file) : file_(file), mapped_(file) {}

  HairFile read() {
    if (mapped_.size() < kHeaderBytes)
      fail("is " + std::to_string(mapped_.size()) + " bytes, shorter than the 128-byte .hair header");
    HairHeader header;
    std::memcpy(&header, mapped_.data(), kHeaderBytes);
    if (std::memcmp(header.magic, "HAIR", 4) != 0) fail("does not start with \"HAIR\": not a .hair file");
    if (!(header.arrays & kPoints)) fail("has no points array (bit 1 of its array flags)");
    check_size(header);

    const char* next = mapped_.data() + kHeaderBytes;
    HairFile hair;
    hair.strand_points.reserve(header.strands);
    std::uint64_t total = 0;
    for (std::uint32_t s = 0; s < header.strands; ++s) {
      const std::uint32_t segments =
          header.arrays & kSegments ? read_at<std::uint16_t>(next, s) : header.default_segments;
      total += std::uint64_t{segments} + 1;
      if (total > header.points)
        fail("declares " + std::to_string(header.points) + " points, but its first " + std::to_string(s + 1) +
             " strands already need " + std::to_string(total));
      hair.strand_points.push_back(segments + 1);
    }
    if (total != header.points)
      fail("declares " + std::to_string(header.points) + " points, but its strands have " + std::to_string(total));
    if (header.arrays & kSegments) next += 2 * std::size_t{header.strands};

    const char* positions = next;
    next += 12 * std::size_t{header.points};
    const char* thickness = header.arrays & kThickness ? next : nullptr;
    if (thickness) next += 4 * std::size_t{header.points};
    if (header.arrays & kTransparency) next += 4 * std::size_t{header.points};  // not rendered
    const char* colors = header.arrays & kColor ? next : nullptr;

    if (!thickness) check_thickness(header.default_thickness, "its default thickness");
    hair.points.resize(header.points);
    for (std::uint32_t i = 0; i < header.points; ++i) {
      const Vec3 p(read_at<float>(positions, 3 * std::size_t{i}), read_at<float>(positions, 3 * std::size_t{i} + 1),
                   read_at<float>(positions, 3 * std::size_t{i} + 2));
      if (!is_finite(p) || max_component(abs(p)) >= kMaxAbsCoordinate)
        fail("has point " + std::to_string(i) + " at a non-finite or huge coordinate");
      const float diameter = thickness ? read_at<float>(thickness, i) : header.default_thickness;
      if (thickness) check_thickness(diameter, "point " + std::to_string(i));
      hair.points[i] = {p, 0.5f * diameter};
    }
    if (colors) {
      hair.colors.resize(header.points);
      for (std::uint32_t i = 0; i < header.points; ++i) {
        const Color c(read_at<float>(colors, 3 * std::size_t{i}), read_at<float>(colors, 3 * std::size_t{i} + 1),
                      read_at<float>(colors, 3 * std::size_t{i} + 2));
        if (!is_finite(c) || c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
          fail("has point " + std::to_string(i) + " with a negative or non-finite colour");
        hair.colors[i] = c;
      }
    }
    return hair;
  }

 private:
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(SourceLocation{file_.string()}, "hair file '" + printable_text(file_.string()) + "' " + problem);
  }

  void check_thickness(float diameter, const std::string& what) const {
    if (!(diameter > 0.0f) || !std::isfinite(diameter))
      fail("gives " + what + " a thickness of " + std::to_string(diameter) + "; thickness must be > 0 and finite");
  }

  // The arrays the header declares must fit in the file: checked in 64 bits before anything is
  // allocated, so a header claiming 10^9 strands is refused at once.
  void check_size(const HairHeader& header) const {
    if (header.points > kMaxMeshElements || header.strands > kMaxMeshElements)
      fail("declares more points or strands than rtpro can index");
    if (header.strands > header.points)
      fail("declares " + std::to_string(header.strands) + " strands but only " + std::to_string(header.points) +
           " points; every strand has at least one");
    const std::uint64_t points = header.points;
    std::uint64_t bytes = kHeaderBytes + 12 * points;
    if (header.arrays & kSegments) bytes += 2 * std::uint64_t{header.strands};
    if (header.arrays & kThickness) bytes += 4 * points;
    if (header.arrays & kTransparency) bytes += 4 * points;
    if (header.arrays & kColor) bytes += 12 * points;
    if (bytes > mapped_.size())
      fail("is truncated: its header declares " + std::to_string(header.strands) + " strands and " +
           std::to_string(header.points) + " points (" + std::to_string(bytes) + " bytes), but the file has " +
           std::to_string(mapped_.size()));
  }

  const std::filesystem::path& file_;
  MappedFile mapped_;
};

}  // namespace

HairFile read_hair_file(const std::filesystem::path& file) { return HairReader(file).read(); }

}  // namespace rtpro
