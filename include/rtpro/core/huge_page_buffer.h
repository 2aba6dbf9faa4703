#pragma once
// An array of trivially copyable T in memory that asks the kernel for transparent huge pages, for
// large arrays written at once (a BVH builder's scratch arrays, tens of MB for a million
// triangles; a film's per-pixel sums). On these virtual machines a 4 KiB page fault costs ~13 us;
// with 2 MiB pages a 38 MB array takes a few dozen faults instead of nearly ten thousand. Pages
// never written are never touched, and every element reads as zero bytes until written (the
// kernel's fresh pages are zero).
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>

namespace rtpro {

template <typename T>
class HugePageBuffer {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

 public:
  HugePageBuffer() = default;
  explicit HugePageBuffer(std::size_t count) : count_(count), bytes_(rounded(count * sizeof(T))) {
    if (bytes_ == 0) return;
    void* memory = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED) throw std::bad_alloc();
    madvise(memory, bytes_, MADV_HUGEPAGE);  // advice: without it the buffer works with 4 KiB pages
    data_ = static_cast<T*>(memory);
  }
  HugePageBuffer(HugePageBuffer&& other) noexcept : data_(other.data_), count_(other.count_), bytes_(other.bytes_) {
    other.data_ = nullptr;
    other.count_ = 0;
    other.bytes_ = 0;
  }
  HugePageBuffer& operator=(HugePageBuffer&& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(count_, other.count_);
    std::swap(bytes_, other.bytes_);
    return *this;
  }
  ~HugePageBuffer() {
    if (data_) munmap(data_, bytes_);
  }

  T* get() const { return data_; }
  T& operator[](std::size_t i) const { return data_[i]; }
  std::size_t size() const { return count_; }

  // Faults the elements' pages in now (not the mapping's rounding to whole huge pages), on this
  // thread, still zero: a buffer that several threads go on to write side by side would otherwise
  // take its first faults in all of them, and two threads faulting the same 2 MiB page each zero
  // one, of which the kernel keeps one (a film's 16 MB cost a 1-spp frame's tiles 6 ms that way).
  void populate() const {
    const std::size_t used = (count_ * sizeof(T) + 4095) / 4096 * 4096;
    if (used == 0) return;
#ifdef MADV_POPULATE_WRITE
    if (madvise(data_, used, MADV_POPULATE_WRITE) == 0) return;
#endif
    // Kernels before 5.14: a write of zero to each 4 KiB page does the same.
    auto* bytes = static_cast<volatile unsigned char*>(static_cast<void*>(data_));
    for (std::size_t byte = 0; byte < used; byte += 4096) bytes[byte] = 0;
  }

 private:
  static constexpr std::size_t kHugePage = std::size_t{2} << 20;
  static std::size_t rounded(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

  T* data_ = nullptr;
  std::size_t count_ = 0;
  std::size_t bytes_ = 0;
};

// Asks for transparent huge pages for [data, data + bytes), memory not yet written: a vector's
// reserved capacity before it is resized, for example; the kernel backs each 2 MiB-aligned part
// on its first write. The advice covers every 4 KiB page the range touches, its partly covered
// first and last ones too: a 2 MiB page can only be huge if each of its 4 KiB pages has the advice,
// and a malloc'd block ends a few bytes into its mapping's last page (left out, the last 2 MiB of a
// 12 MiB image took 511 faults of ~13 us). The advice changes no data, so pages the range shares
// with a neighbouring block lose nothing.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kPage = 4096;
  const auto begin = reinterpret_cast<std::uintptr_t>(data) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes + kPage - 1) & ~(kPage - 1);
  if (bytes > 0) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

// A std::allocator that takes memory for large arrays (4 MiB and more) the way HugePageBuffer
// does, so that a finished BVH's nodes and leaf rows are written into huge pages too (a ray's
// walk through a million-triangle BVH touches a new 4 KiB page at nearly every node: the TLB
// misses cost as much as the cache misses); small arrays, such as the BVHs of small prototypes,
// come from the heap as usual, aligned as T asks (mmap's pages are aligned more than any T).
template <typename T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t kLarge = std::size_t{4} << 20;
  static constexpr bool kOverAligned = alignof(T) > __STDCPP_DEFAULT_NEW_ALIGNMENT__;

  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kLarge) {
      if constexpr (kOverAligned) return static_cast<T*>(::operator new (bytes, std::align_val_t{alignof(T)}));
      return static_cast<T*>(::operator new(bytes));
    }
    void* memory = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (memory == MAP_FAILED) throw std::bad_alloc();
    madvise(memory, bytes, MADV_HUGEPAGE);
    return static_cast<T*>(memory);
  }
  void deallocate(T* p, std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kLarge) {
      if constexpr (kOverAligned) return ::operator delete (p, std::align_val_t{alignof(T)});
      return ::operator delete(p);
    }
    munmap(p, bytes);
  }
  template <typename U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }
};

}  // namespace rtpro
