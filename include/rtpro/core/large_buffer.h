#pragma once
// Large arrays that a loader fills once. On the virtual machines rtpro runs on, touching fresh
// memory for the first time (one page fault per 4 KB page) costs about 0.7 ms per MB, more than
// parsing the text that fills it; 2 MB pages cut that about threefold. So large buffers ask the
// kernel for transparent huge pages (a no-op where they are disabled).
#include "rtpro/core/huge_page_buffer.h"

#include <cstddef>
#include <vector>

namespace rtpro {

// Reserves n elements, in 2 MB pages when they take two or more (advise_huge_pages).
template <typename T, typename Allocator>
void reserve_large(std::vector<T, Allocator>& v, std::size_t n) {
  v.reserve(n);
  constexpr std::size_t kWorthIt = std::size_t(4) << 20;  // two huge pages
  if (n * sizeof(T) >= kWorthIt) advise_huge_pages(v.data(), n * sizeof(T));
}

// Resizes an empty vector to n value-initialised elements.
template <typename T, typename Allocator>
void resize_large(std::vector<T, Allocator>& v, std::size_t n) {
  reserve_large(v, n);
  v.resize(n);
}

}  // namespace rtpro
