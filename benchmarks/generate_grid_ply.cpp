// Writes a binary little-endian PLY of exactly N unique triangles for the scale benchmark
// (benchmarks/scale_benchmark.sh): a grid of quads over the unit square in x and z, two triangles
// each, displaced in y by a sum of sines, so that no two triangles are alike and the BVH has real
// depth. Deterministic: the same N always gives the same bytes.
//   rtpro_generate_grid_ply TRIANGLES OUTPUT.ply
// TRIANGLES may end in M (millions), e.g. 100M. Writes in blocks: memory stays a few MB.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

static_assert(std::endian::native == std::endian::little, "the PLY is written in the machine's byte order");

std::uint64_t parse_count(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const double scale = (*end == 'M' || *end == 'm') ? 1e6 : 1.0;
  if (end == text.c_str() || value <= 0 || !(value * scale < 4e9)) return 0;
  return static_cast<std::uint64_t>(std::llround(value * scale));
}

float height(double x, double z) {
  return static_cast<float>(0.02 * std::sin(37.0 * x) * std::cos(23.0 * z) + 0.01 * std::sin(91.0 * (x + z)) +
                            0.004 * std::cos(211.0 * x - 173.0 * z));
}

class BlockWriter {
 public:
  explicit BlockWriter(std::FILE* file) : file_(file) { buffer_.reserve(kBlock + 64); }
  ~BlockWriter() { flush(); }
  template <typename T>
  void put(const T& value) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    buffer_.insert(buffer_.end(), bytes, bytes + sizeof(T));
    if (buffer_.size() >= kBlock) flush();
  }
  void flush() {
    if (!buffer_.empty() && std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
      std::perror("write");
      std::exit(1);
    }
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kBlock = std::size_t{4} << 20;
  std::FILE* file_;
  std::vector<unsigned char> buffer_;
};

}  // namespace

int main(int argc, char** argv) {
  const std::uint64_t triangles = argc == 3 ? parse_count(argv[1]) : 0;
  if (triangles == 0) {
    std::fprintf(stderr, "usage: %s TRIANGLES OUTPUT.ply (TRIANGLES: a count such as 1000000 or 10M)\n", argv[0]);
    return 2;
  }
  // Columns of quads × rows, nearly square, with enough quads for every triangle; the last row's
  // unused quads write no triangles (their vertices stay, unreferenced: at most one row).
  const std::uint64_t quads = (triangles + 1) / 2;
  const auto columns = static_cast<std::uint64_t>(std::ceil(std::sqrt(double(quads))));
  const std::uint64_t rows = (quads + columns - 1) / columns;
  const std::uint64_t vertices = (columns + 1) * (rows + 1);
  if (vertices > INT32_MAX) {
    std::fprintf(stderr, "%llu vertices do not fit PLY int indices\n", static_cast<unsigned long long>(vertices));
    return 2;
  }
  std::FILE* file = std::fopen(argv[2], "wb");
  if (!file) {
    std::perror(argv[2]);
    return 1;
  }
  std::fprintf(file,
               "ply\nformat binary_little_endian 1.0\ncomment rtpro_generate_grid_ply %llu\n"
               "element vertex %llu\nproperty float x\nproperty float y\nproperty float z\n"
               "element face %llu\nproperty list uchar int vertex_indices\nend_header\n",
               static_cast<unsigned long long>(triangles), static_cast<unsigned long long>(vertices),
               static_cast<unsigned long long>(triangles));
  {
    BlockWriter out(file);
    for (std::uint64_t r = 0; r <= rows; ++r) {
      const double z = double(r) / double(rows);
      for (std::uint64_t c = 0; c <= columns; ++c) {
        const double x = double(c) / double(columns);
        out.put(static_cast<float>(x));
        out.put(height(x, z));
        out.put(static_cast<float>(z));
      }
    }
    std::uint64_t written = 0;
    for (std::uint64_t r = 0; r < rows && written < triangles; ++r) {
      for (std::uint64_t c = 0; c < columns && written < triangles; ++c) {
        const auto v00 = static_cast<std::int32_t>(r * (columns + 1) + c);
        const std::int32_t v10 = v00 + 1, v01 = v00 + static_cast<std::int32_t>(columns + 1), v11 = v01 + 1;
        // Counter-clockwise seen from +y: the grid faces up.
        const std::int32_t corners[2][3] = {{v00, v01, v10}, {v10, v01, v11}};
        for (const auto& tri : corners) {
          if (written == triangles) break;
          out.put(std::uint8_t{3});
          for (const std::int32_t index : tri) out.put(index);
          ++written;
        }
      }
    }
  }
  if (std::fclose(file) != 0) {
    std::perror(argv[2]);
    return 1;
  }
  return 0;
}
