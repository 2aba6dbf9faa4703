// What mesh.h promises the code that reads a mesh as Embree and the surface batch do: a vertex is
// 12 bytes, and 16 bytes from any vertex of a VertexArray are readable (under AddressSanitizer, a
// read past the allocation fails the test), past the last one zeroes.
#include "rtpro/scene/mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <utility>

namespace rtpro {
namespace mesh_test {

// The four floats a 16-byte load from vertex i sees.
std::array<float, 4> load16(const VertexArray& vertices, std::size_t i) {
  std::array<float, 4> lanes;
  std::memcpy(lanes.data(), &vertices[i].x, sizeof(lanes));
  return lanes;
}

TEST(VertexArray, SixteenBytesFromTheLastVertexAreReadableAndZero) {
  for (std::size_t count : {std::size_t{1}, std::size_t{2}, std::size_t{3}, std::size_t{1000}}) {
    VertexArray vertices;
    for (std::size_t i = 0; i < count; ++i) vertices.push_back({float(i) + 1.0f, -2.0f, 3.0f});
    vertices.shrink_to_fit();  // capacity == size: nothing but the slack lies past the last vertex
    ASSERT_EQ(vertices.capacity(), count);
    const std::array<float, 4> last = load16(vertices, count - 1);
    EXPECT_EQ(last[0], float(count));
    EXPECT_EQ(last[1], -2.0f);
    EXPECT_EQ(last[2], 3.0f);
    EXPECT_EQ(last[3], 0.0f) << count;
    // Elsewhere the fourth lane is the next vertex's x.
    if (count > 1) {
      EXPECT_EQ(load16(vertices, 0)[3], 2.0f);
    }
  }
}

TEST(VertexArray, CopiesAndMovesKeepTheSlack) {
  VertexArray vertices(5, MeshVertex{1.0f, 2.0f, 3.0f});
  const VertexArray copy = vertices;
  EXPECT_EQ(load16(copy, 4)[3], 0.0f);
  const VertexArray moved = std::move(vertices);
  EXPECT_EQ(load16(moved, 4)[3], 0.0f);
  EXPECT_EQ(sizeof(MeshVertex), 12u);
}

TEST(VertexArray, AnImpossibleSizeIsABadAllocNotAWrappedOne) {
  OverreadAllocator<MeshVertex> allocator;
  EXPECT_THROW((void)allocator.allocate(std::size_t(-1) / 4), std::bad_array_new_length);
}

}  // namespace mesh_test
}  // namespace rtpro
