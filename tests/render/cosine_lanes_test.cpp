// The Lambert directions worked out four at a time must be sample_cosine_hemisphere's, bit for
// bit, for every sample (the path integrator uses them in its place), in whichever wedge of the
// disk and at its special points: the centre, the diagonals, the rim.
#include "cosine_lanes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace rtpro {
namespace cosine_lanes_test {

struct Record {
  Sample2D u;
  float unrelated;
  Vec3 direction;
};

bool same(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

TEST(CosineLanes, EveryDirectionIsTheScalarOneBitForBit) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<Record> records;
  const float special[] = {0.0f, 0.25f, 0.5f, 0.75f, 0x1.fffffep-1f, 0x1p-24f, 0.5f - 0x1p-25f};
  for (float a : special)
    for (float b : special) records.push_back({{a, b}, -1.0f, {}});
  for (int i = 0; i < 100000; ++i) {
    const float a = unit(rng);
    // A third on a diagonal, where |x| == |y| and the wedges meet.
    records.push_back({{a, i % 3 == 0 ? (i % 2 ? a : 1.0f - a) : unit(rng)}, -1.0f, {}});
  }
  // Every count from 0 to 9, so that the lanes and the scalar tail both run.
  for (std::size_t count = 0; count < 10; ++count) {
    std::vector<Record> few(records.begin(), records.begin() + static_cast<std::ptrdiff_t>(count));
    if (!few.empty()) sample_cosine_hemispheres(few.size(), &few[0].u, &few[0].direction, sizeof(Record));
    for (const Record& r : few) {
      const Vec3 expected = sample_cosine_hemisphere(r.u);
      ASSERT_TRUE(same(r.direction.x, expected.x) && same(r.direction.y, expected.y) &&
                  same(r.direction.z, expected.z));
    }
  }
  sample_cosine_hemispheres(records.size(), &records[0].u, &records[0].direction, sizeof(Record));
  for (std::size_t i = 0; i < records.size(); ++i) {
    const Vec3 expected = sample_cosine_hemisphere(records[i].u);
    ASSERT_TRUE(same(records[i].direction.x, expected.x) && same(records[i].direction.y, expected.y) &&
                same(records[i].direction.z, expected.z))
        << "sample " << i << ": (" << records[i].u.x << ", " << records[i].u.y << ")";
    ASSERT_EQ(records[i].unrelated, -1.0f);  // only the directions are written
  }
}

}  // namespace cosine_lanes_test
}  // namespace rtpro
