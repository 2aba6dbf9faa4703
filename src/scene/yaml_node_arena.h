#pragma once
// Memory for the nodes of YAML documents: the nodes, their lists of items and entries, and their
// text, given out from large blocks that ask the kernel for transparent huge pages and released
// all at once with the arena. Nodes hold only views into the arena, so none needs destroying.
//
// Why: a fresh process spent most of its load time on page faults and allocations, not parsing.
// The 10,000-sphere scene builds ~80,000 nodes; one 4 KiB fault costs ~13 us on these virtual
// machines, and a reference-counted node with its own control block and heap strings took
// ~1.6 KB per sphere to build, count and free. Here a sphere takes ~0.5 KB of plain records.
#include "yaml_document.h"

#include <memory_resource>
#include <span>
#include <string_view>
#include <vector>

namespace rtpro {

class YamlNodeArena {
 public:
  YamlNodeArena();
  YamlNodeArena(const YamlNodeArena&) = delete;
  YamlNodeArena& operator=(const YamlNodeArena&) = delete;

  // A node in the arena, a copy of `init`, to fill in before it is shared.
  YamlNode* node(const YamlNode& init = YamlNode{});
  std::string_view text(std::string_view bytes);
  YamlNodeList list(std::span<const YamlNodePtr> items);
  YamlEntryList list(std::span<const YamlEntry> entries);

 private:
  template <typename T>
  std::span<const T> copy(std::span<const T> values);

  class HugePageBlocks : public std::pmr::memory_resource {
    void* do_allocate(std::size_t bytes, std::size_t alignment) override;
    void do_deallocate(void* block, std::size_t bytes, std::size_t alignment) override;
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }
  };

  HugePageBlocks pages_;
  std::pmr::monotonic_buffer_resource blocks_;
};

}  // namespace rtpro
