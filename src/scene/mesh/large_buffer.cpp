#include "large_buffer.h"

#include <cstdint>
#include <sys/mman.h>

namespace rtpro {

void advise_huge_pages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kPage = 4096;
  constexpr std::size_t kWorthIt = std::size_t(4) << 20;  // two huge pages
  if (bytes < kWorthIt) return;
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
  // Only advice: if the kernel refuses, the buffer simply keeps 4 KB pages.
  ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

}  // namespace rtpro
