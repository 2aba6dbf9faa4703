// The huge-page buffer reads as zeros until written, and populate() makes its elements' pages
// resident at once (what the film relies on: zero sums, faulted in before its tiles come).
#include "rtpro/core/huge_page_buffer.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace rtpro {
namespace huge_page_buffer_test {

// How many of the 4 KiB pages of [data, data + bytes) are resident.
std::size_t resident_pages(const void* data, std::size_t bytes) {
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  std::vector<unsigned char> state((bytes + page - 1) / page);
  EXPECT_EQ(mincore(const_cast<void*>(data), bytes, state.data()), 0);
  std::size_t resident = 0;
  for (const unsigned char s : state) resident += s & 1u;
  return resident;
}

TEST(HugePageBuffer, ReadsAsZeroUntilWritten) {
  const HugePageBuffer<float> buffer(3 * 1024 * 1024 + 5);  // past a whole number of huge pages
  EXPECT_EQ(buffer.size(), std::size_t{3 * 1024 * 1024 + 5});
  for (const std::size_t i : {std::size_t{0}, std::size_t{1234567}, buffer.size() - 1}) EXPECT_EQ(buffer[i], 0.0f);
  buffer[7] = 2.5f;
  EXPECT_EQ(buffer[7], 2.5f);
  EXPECT_EQ(buffer[8], 0.0f);
}

TEST(HugePageBuffer, PopulateMakesEveryPageOfTheElementsResidentAndZero) {
  const std::size_t count = 5 * 1024 * 1024 + 17;  // 20 MB and a bit
  const HugePageBuffer<float> buffer(count);
  const std::size_t bytes = count * sizeof(float);
  const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  const std::size_t pages = (bytes + page - 1) / page;
  EXPECT_EQ(resident_pages(buffer.get(), bytes), 0u) << "nothing is touched before populate";
  buffer.populate();
  EXPECT_EQ(resident_pages(buffer.get(), bytes), pages);
  std::uint32_t any = 0;
  for (std::size_t i = 0; i < count; i += 1021) any |= buffer[i] != 0.0f;
  EXPECT_EQ(buffer[count - 1], 0.0f);
  EXPECT_EQ(any, 0u);
}

TEST(HugePageBuffer, MovesKeepTheElementsAndTheirCount) {
  HugePageBuffer<int> a(1000);
  a[999] = 42;
  HugePageBuffer<int> b(std::move(a));
  EXPECT_EQ(b.size(), 1000u);
  EXPECT_EQ(b[999], 42);
  EXPECT_EQ(a.size(), 0u);
  EXPECT_EQ(a.get(), nullptr);
  HugePageBuffer<int> c;
  c = std::move(b);
  EXPECT_EQ(c.size(), 1000u);
  EXPECT_EQ(c[999], 42);
  HugePageBuffer<int>().populate();  // nothing to populate
}

}  // namespace huge_page_buffer_test
}  // namespace rtpro
