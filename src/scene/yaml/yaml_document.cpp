#include "yaml_document.h"

#include "yaml_node_arena.h"
#include "yaml_tree_builder.h"
#include "rtpro/scene/scene_parser.h"

#include <algorithm>
#include <charconv>
#include <cstring>

namespace rtpro {

SourceLocation YamlPosition::location() const { return SourceLocation{source ? *source : std::string(), line, column}; }

const YamlEntry* YamlNode::find(std::string_view key) const {
  for (const YamlEntry& entry : entries())
    if (entry.key == key) return &entry;
  return nullptr;
}

std::string YamlNode::describe() const {
  switch (kind) {
    case Kind::null: return "an empty value";
    case Kind::scalar: {
      constexpr std::size_t kShown = 40;
      const std::string_view text = scalar();
      const std::string shown = text.size() > kShown ? std::string(text.substr(0, kShown)) + "..." : std::string(text);
      return (plain ? "'" : "the quoted string '") + shown + "'";
    }
    case Kind::sequence: return "a list of " + std::to_string(size_) + (size_ == 1 ? " item" : " items");
    case Kind::mapping: return "a mapping";
  }
  return "a value";
}

// memchr finds the line ends: milliseconds even for hundreds of MB.
void LineLengthGuard::feed(std::string_view bytes) {
  while (!bytes.empty()) {
    const void* found = std::memchr(bytes.data(), '\n', bytes.size());
    const std::size_t length =
        found ? static_cast<std::size_t>(static_cast<const char*>(found) - bytes.data()) : bytes.size();
    current_ += length;
    if (current_ > kMaxYamlLineBytes) {
      throw InputError(SourceLocation{source_, line_, static_cast<int>(kMaxYamlLineBytes) + 1},
                       "line " + std::to_string(line_) + " is longer than the limit of " +
                           std::to_string(kMaxYamlLineBytes >> 20) +
                           " MiB per line (put large data in mesh files, not in the scene)");
    }
    if (!found) return;
    bytes.remove_prefix(length + 1);
    current_ = 0;
    ++line_;
  }
}

namespace {

// A copy of `node` (or a new mapping where there is nothing) with segments[i..] set to `value`.
// Copies only the path, so aliases elsewhere keep the original subtree.
YamlNodePtr with_value_at(YamlNodeArena& arena, YamlNodePtr node, const std::vector<std::string>& segments,
                          std::size_t i, YamlNodePtr value, const YamlPosition& at) {
  if (i == segments.size()) return value;
  const std::string& segment = segments[i];
  const std::string parent = i == 0 ? std::string("the scene") : "'" + segments[i - 1] + "'";
  YamlNode base = node ? *node : YamlNode{};
  if (base.is_null()) {
    base.kind = YamlNode::Kind::mapping;
    base.at = at;
  }
  if (base.is_mapping()) {
    std::vector<YamlEntry> entries(base.entries().begin(), base.entries().end());
    const auto same =
        std::find_if(entries.begin(), entries.end(), [&](const YamlEntry& e) { return e.key == segment; });
    if (same != entries.end()) {
      same->value = with_value_at(arena, same->value, segments, i + 1, value, at);
    } else {
      entries.push_back({arena.text(segment), at, with_value_at(arena, nullptr, segments, i + 1, value, at)});
    }
    return arena.with_entries(base, entries);
  }
  if (base.is_sequence()) {
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
    if (error != std::errc() || end != segment.data() + segment.size() || index >= base.items().size()) {
      throw InputError(at.location(), parent + " is a list of " + std::to_string(base.items().size()) +
                                          " items; expected an index from 0, got '" + segment + "'");
    }
    std::vector<YamlNodePtr> items(base.items().begin(), base.items().end());
    items[index] = with_value_at(arena, items[index], segments, i + 1, value, at);
    return arena.with_items(base, items);
  }
  throw InputError(at.location(), parent + " is a single value, so it has no key '" + segment + "'");
}

struct OverrideKey {
  std::vector<std::string> segments;
  std::size_t equals = 0;  // where the value starts, less one
};

// A --set key: names separated by dots, ended by '='. A name with a dot or '=' in it (Blender
// names materials "Material.001") is quoted, "..." or '...', as one segment.
OverrideKey split_override_key(const std::string& text, const YamlPosition& at) {
  OverrideKey key;
  std::size_t pos = 0;
  while (true) {
    if (pos < text.size() && (text[pos] == '"' || text[pos] == '\'')) {
      const std::size_t close = text.find(text[pos], pos + 1);
      if (close == std::string::npos)
        throw InputError(at.location(), "a quoted key name has no closing " + std::string(1, text[pos]));
      key.segments.push_back(text.substr(pos + 1, close - pos - 1));
      pos = close + 1;
    } else {
      const std::size_t end = std::min(text.find('.', pos), text.find('=', pos));
      key.segments.push_back(text.substr(pos, end == std::string::npos ? std::string::npos : end - pos));
      pos = end;
    }
    if (key.segments.back().empty()) throw InputError(at.location(), "empty key name");
    if (pos >= text.size() || (text[pos] != '.' && text[pos] != '='))
      throw InputError(at.location(),
                       "expected key=value, e.g. render.spp=64 (a name with a dot in it is quoted: "
                       "materials.\"Material.001\".color=[1,0,0])");
    if (text[pos] == '=') {
      key.equals = pos;
      return key;
    }
    ++pos;
  }
}

}  // namespace

std::filesystem::path include_identity(const std::filesystem::path& file) {
  std::error_code error;
  std::filesystem::path canonical = std::filesystem::weakly_canonical(file, error);
  return error ? file.lexically_normal() : canonical;
}

YamlDocument YamlDocument::parse(std::string_view text, const std::string& source_name,
                                 const YamlFileReader& read_include) {
  IncludeWalk walk;
  return parse_included(text, source_name, read_include, walk);
}

YamlDocument YamlDocument::parse_included(std::string_view text, const std::string& source_name,
                                          const YamlFileReader& read_include, IncludeWalk& walk) {
  YamlDocument document;
  document.arena_ = std::make_shared<YamlNodeArena>();
  const std::string* source = &document.sources_.emplace_back(source_name);
  LineLengthGuard(*source).feed(text);
  ParsedTree tree = parse_tree(text, source, true, *document.arena_);
  document.root_ = tree.root;
  document.has_includes_ = tree.saw_include;
  document.has_variables_ = tree.saw_dollar;
  if (document.has_includes_ && read_include) {
    walk.chain.push_back(include_identity(source_name));
    document.root_ = document.expand_includes(document.root_, read_include, walk);
    walk.chain.pop_back();
  }
  return document;
}

void YamlDocument::apply_override(const std::string& override_text) {
  const YamlPosition at{&sources_.emplace_back(override_source(override_text)), 0, 0};
  const auto [segments, equals] = split_override_key(override_text, at);
  ParsedTree value = parse_tree(std::string_view(override_text).substr(equals + 1), at.source, false, *arena_);
  if (value.saw_dollar || segments.front() == "variables") has_variables_ = true;
  root_ = with_value_at(*arena_, root_, segments, 0, value.root, at);
}

}  // namespace rtpro
