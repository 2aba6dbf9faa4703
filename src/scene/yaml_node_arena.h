#pragma once
// Memory for the nodes of one parsed YAML document: the nodes themselves and their lists of items
// and entries, given out from large blocks that ask the kernel for transparent huge pages.
//
// Why: a fresh process spent most of its load time on page faults, not parsing. The 10,000-sphere
// scene builds ~80,000 nodes (18 MB touched); one 4 KiB fault costs ~13 us on these virtual
// machines, 60 ms in all against 25 ms for everything else. With 2 MiB pages that is a few dozen
// faults. Blocks are released when the last node that uses them is gone: every node made here
// holds the arena (see make_node).
#include "yaml_document.h"

#include <memory>
#include <memory_resource>

namespace rtpro {

class YamlNodeArena {
 public:
  YamlNodeArena();
  YamlNodeArena(const YamlNodeArena&) = delete;
  YamlNodeArena& operator=(const YamlNodeArena&) = delete;

  std::pmr::memory_resource* resource() { return &blocks_; }

 private:
  class HugePageBlocks : public std::pmr::memory_resource {
    void* do_allocate(std::size_t bytes, std::size_t alignment) override;
    void do_deallocate(void* block, std::size_t bytes, std::size_t alignment) override;
    bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }
  };

  HugePageBlocks pages_;
  std::pmr::monotonic_buffer_resource blocks_;
};

// A node whose memory, and that of its lists, comes from `arena`, which it keeps alive.
std::shared_ptr<YamlNode> make_node(const std::shared_ptr<YamlNodeArena>& arena);

}  // namespace rtpro
