#pragma once
// Memory for the nodes of YAML documents: the nodes, their lists of items and entries, and their
// text, given out from large blocks and released all at once with the arena. Nodes hold only
// views into the arena, so none needs destroying.
//
// Why: reference-counted nodes with their own control blocks and heap strings took ~1.6 KB per
// sphere of the 10,000-sphere scene to build, count and free, and the load 0.035 s; here a sphere
// takes ~0.5 KB of plain records and the load 0.025 s. The blocks are ordinary pages: asking for
// transparent huge pages (MADV_HUGEPAGE) made the load 0.023 s on a quiet machine but 0.022-0.072 s
// (median 0.037) right after another process's exit, against 0.025-0.029 s with ordinary pages
// (third_party_notes/libyaml.md).
#include "yaml_document.h"

#include <memory_resource>
#include <span>
#include <string_view>

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
  // A copy of `node` whose items (entries) are copies of `items` (`entries`): how a changed list
  // or mapping is made, its unchanged children shared.
  YamlNodePtr with_items(const YamlNode& node, std::span<const YamlNodePtr> items);
  YamlNodePtr with_entries(const YamlNode& node, std::span<const YamlEntry> entries);

 private:
  template <typename T>
  std::span<const T> copy(std::span<const T> values);

  std::pmr::monotonic_buffer_resource blocks_;
};

}  // namespace rtpro
