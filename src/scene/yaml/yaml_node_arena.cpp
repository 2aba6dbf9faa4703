#include "yaml_node_arena.h"

#include <cstring>
#include <memory>
#include <new>
#include <type_traits>

namespace rtpro {

namespace {

constexpr std::size_t kFirstBlock = std::size_t{1} << 20;  // later blocks grow geometrically

// The arena never runs destructors.
static_assert(std::is_trivially_destructible_v<YamlNode>);
static_assert(sizeof(YamlNode) == 32);
static_assert(std::is_trivially_copyable_v<YamlEntry>);

}  // namespace

YamlNodeArena::YamlNodeArena() : blocks_(kFirstBlock) {}

YamlNode* YamlNodeArena::node(const YamlNode& init) {
  return new (blocks_.allocate(sizeof(YamlNode), alignof(YamlNode))) YamlNode(init);
}

std::string_view YamlNodeArena::text(std::string_view bytes) {
  if (bytes.empty()) return {};
  char* copy = static_cast<char*>(blocks_.allocate(bytes.size(), 1));
  std::memcpy(copy, bytes.data(), bytes.size());
  return {copy, bytes.size()};
}

template <typename T>
std::span<const T> YamlNodeArena::copy(std::span<const T> values) {
  if (values.empty()) return {};
  T* copy = static_cast<T*>(blocks_.allocate(values.size_bytes(), alignof(T)));
  std::uninitialized_copy(values.begin(), values.end(), copy);
  return {copy, values.size()};
}

YamlNodeList YamlNodeArena::list(std::span<const YamlNodePtr> items) { return copy(items); }

YamlEntryList YamlNodeArena::list(std::span<const YamlEntry> entries) { return copy(entries); }

YamlNodePtr YamlNodeArena::with_items(const YamlNode& node, std::span<const YamlNodePtr> items) {
  YamlNode* copy = this->node(node);
  copy->set_items(list(items));
  return copy;
}

YamlNodePtr YamlNodeArena::with_entries(const YamlNode& node, std::span<const YamlEntry> entries) {
  YamlNode* copy = this->node(node);
  copy->set_entries(list(entries));
  return copy;
}

}  // namespace rtpro
