#include "yaml_node_arena.h"

#include <sys/mman.h>

#include <new>

namespace rtpro {

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// The allocator of a node's shared_ptr control block: it owns a reference to the arena, so the
// arena lives as long as any of its nodes.
template <typename T>
struct ArenaAllocator {
  using value_type = T;
  std::shared_ptr<YamlNodeArena> arena;

  explicit ArenaAllocator(std::shared_ptr<YamlNodeArena> owner) : arena(std::move(owner)) {}
  template <typename U>
  ArenaAllocator(const ArenaAllocator<U>& other) : arena(other.arena) {}
  T* allocate(std::size_t n) { return static_cast<T*>(arena->resource()->allocate(n * sizeof(T), alignof(T))); }
  void deallocate(T*, std::size_t) {}  // the blocks are released all at once
  template <typename U>
  bool operator==(const ArenaAllocator<U>& other) const {
    return arena == other.arena;
  }
};

}  // namespace

void* YamlNodeArena::HugePageBlocks::do_allocate(std::size_t bytes, std::size_t) {
  const std::size_t size = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* block = mmap(nullptr, size, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (block == MAP_FAILED) throw std::bad_alloc();
  madvise(block, size, MADV_HUGEPAGE);  // advice only: without it the block works with 4 KiB pages
  return block;
}

void YamlNodeArena::HugePageBlocks::do_deallocate(void* block, std::size_t bytes, std::size_t) {
  munmap(block, (bytes + kHugePage - 1) / kHugePage * kHugePage);
}

YamlNodeArena::YamlNodeArena() : blocks_(kHugePage, &pages_) {}

std::shared_ptr<YamlNode> make_node(const std::shared_ptr<YamlNodeArena>& arena) {
  return std::allocate_shared<YamlNode>(ArenaAllocator<YamlNode>(arena), arena->resource());
}

}  // namespace rtpro
