#include "yaml_document.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/mark.h>
#include <yaml-cpp/parser.h>

#include <charconv>
#include <cstring>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace rtpro {

SourceLocation YamlPosition::location() const { return SourceLocation{source ? *source : std::string(), line, column}; }

const YamlEntry* YamlNode::find(std::string_view key) const {
  for (const YamlEntry& entry : entries)
    if (entry.key == key) return &entry;
  return nullptr;
}

std::string YamlNode::describe() const {
  switch (kind) {
    case Kind::null:
      return "an empty value";
    case Kind::scalar: {
      constexpr std::size_t kShown = 40;
      const std::string shown = scalar.size() > kShown ? scalar.substr(0, kShown) + "..." : scalar;
      return (plain ? "'" : "the quoted string '") + shown + "'";
    }
    case Kind::sequence:
      return "a list of " + std::to_string(items.size()) + (items.size() == 1 ? " item" : " items");
    case Kind::mapping:
      return "a mapping";
  }
  return "a value";
}

// memchr finds the line ends: milliseconds even for hundreds of MB.
void LineLengthGuard::feed(std::string_view bytes) {
  while (!bytes.empty()) {
    const void* found = std::memchr(bytes.data(), '\n', bytes.size());
    const std::size_t length = found ? static_cast<std::size_t>(static_cast<const char*>(found) - bytes.data()) : bytes.size();
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

// Turns yaml-cpp's parse events into YamlNodes. Positions are yaml-cpp's 0-based marks made
// 1-based, or 0 when `known_positions` is false (override values).
class TreeBuilder : public YAML::EventHandler {
 public:
  TreeBuilder(const std::string* source, bool known_positions) : source_(source), known_positions_(known_positions) {}

  YamlNodePtr root() const { return root_ ? root_ : null_node(position(YAML::Mark())); }

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents_ > 1) fail(mark, "more than one YAML document ('---'); a scene is one document");
  }
  void OnDocumentEnd() override {}

  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { complete(null_node(position(mark)), anchor); }

  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const auto found = anchors_.find(anchor);
    if (found == anchors_.end()) fail(mark, "alias refers to a node that contains it");
    complete(found->second, 0);
  }

  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    // yaml-cpp tags plain scalars "?" and quoted or block scalars "!".
    if (tag != "?" && tag != "!") fail(mark, "YAML tags ('" + tag + "') are not used in rtpro scenes");
    auto node = std::make_shared<YamlNode>();
    node->kind = YamlNode::Kind::scalar;
    node->at = position(mark);
    node->scalar = value;
    node->plain = tag == "?";
    complete(std::move(node), anchor);
  }

  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, tag, anchor, YamlNode::Kind::sequence);
  }
  void OnSequenceEnd() override { close(); }

  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, tag, anchor, YamlNode::Kind::mapping);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Open {
    std::shared_ptr<YamlNode> node;
    YAML::anchor_t anchor;
    std::optional<YamlEntry> pending;  // a mapping key waiting for its value
  };

  YamlPosition position(const YAML::Mark& mark) const {
    if (!known_positions_ || mark.is_null()) return {source_, 0, 0};
    return {source_, mark.line + 1, mark.column + 1};
  }

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& message) const {
    throw InputError(position(mark).location(), message);
  }

  static YamlNodePtr null_node(YamlPosition at) {
    auto node = std::make_shared<YamlNode>();
    node->at = at;
    return node;
  }

  void open(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor, YamlNode::Kind kind) {
    if (tag != "?" && tag != "!") fail(mark, "YAML tags ('" + tag + "') are not used in rtpro scenes");
    if (open_.size() >= static_cast<std::size_t>(kMaxYamlNesting))
      fail(mark, "YAML nesting deeper than " + std::to_string(kMaxYamlNesting) + " levels");
    auto node = std::make_shared<YamlNode>();
    node->kind = kind;
    node->at = position(mark);
    open_.push_back({std::move(node), anchor, std::nullopt});
  }

  void close() {
    Open done = std::move(open_.back());
    open_.pop_back();
    complete(std::move(done.node), done.anchor);
  }

  void complete(YamlNodePtr node, YAML::anchor_t anchor) {
    if (anchor != 0) anchors_[anchor] = node;
    if (open_.empty()) {
      root_ = std::move(node);
      return;
    }
    Open& parent = open_.back();
    if (parent.node->is_sequence()) {
      parent.node->items.push_back(std::move(node));
    } else if (!parent.pending) {
      parent.pending = key_entry(*parent.node, *node);
    } else {
      YamlEntry entry = std::move(*parent.pending);
      parent.pending.reset();
      // An empty value is reported at its key: yaml-cpp marks it at the next token.
      entry.value = node->is_null() && anchor == 0 ? null_node(entry.key_at) : std::move(node);
      parent.node->entries.push_back(std::move(entry));
    }
  }

  YamlEntry key_entry(const YamlNode& mapping, const YamlNode& key) const {
    if (!key.is_scalar()) {
      throw InputError(key.at.location(), "a mapping key must be a name, got " + key.describe());
    }
    if (const YamlEntry* first = mapping.find(key.scalar)) {
      std::string message = "duplicate key '" + key.scalar + "'";
      if (first->key_at.line > 0) message += " (first given at line " + std::to_string(first->key_at.line) + ")";
      throw InputError(key.at.location(), message);
    }
    return YamlEntry{key.scalar, key.at, nullptr};
  }

  const std::string* source_;
  bool known_positions_;
  int documents_ = 0;
  std::vector<Open> open_;
  std::unordered_map<YAML::anchor_t, YamlNodePtr> anchors_;
  YamlNodePtr root_;
};

YamlNodePtr parse_tree(std::string_view text, const std::string* source, bool known_positions) {
  std::istringstream stream{std::string(text)};
  YAML::Parser parser(stream);
  TreeBuilder builder(source, known_positions);
  try {
    while (parser.HandleNextDocument(builder)) {
    }
  } catch (const YAML::Exception& e) {
    const YamlPosition at = known_positions && !e.mark.is_null()
                                ? YamlPosition{source, e.mark.line + 1, e.mark.column + 1}
                                : YamlPosition{source, 0, 0};
    throw InputError(at.location(), "YAML syntax error: " + e.msg);
  }
  return builder.root();
}

// A copy of `node` (or a new mapping where there is nothing) with segments[i..] set to `value`.
// Copies only the path, so aliases elsewhere keep the original subtree.
YamlNodePtr with_value_at(const YamlNodePtr& node, const std::vector<std::string>& segments, std::size_t i,
                          const YamlNodePtr& value, const YamlPosition& at) {
  if (i == segments.size()) return value;
  const std::string& segment = segments[i];
  const std::string parent = i == 0 ? std::string("the scene") : "'" + segments[i - 1] + "'";
  auto copy = std::make_shared<YamlNode>(node ? *node : YamlNode{});
  if (copy->is_null()) {
    copy->kind = YamlNode::Kind::mapping;
    copy->at = at;
  }
  if (copy->is_mapping()) {
    for (YamlEntry& entry : copy->entries) {
      if (entry.key == segment) {
        entry.value = with_value_at(entry.value, segments, i + 1, value, at);
        return copy;
      }
    }
    copy->entries.push_back({segment, at, with_value_at(nullptr, segments, i + 1, value, at)});
    return copy;
  }
  if (copy->is_sequence()) {
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
    if (error != std::errc() || end != segment.data() + segment.size() || index >= copy->items.size()) {
      throw InputError(at.location(), parent + " is a list of " + std::to_string(copy->items.size()) +
                                          " items; expected an index from 0, got '" + segment + "'");
    }
    copy->items[index] = with_value_at(copy->items[index], segments, i + 1, value, at);
    return copy;
  }
  throw InputError(at.location(), parent + " is a single value, so it has no key '" + segment + "'");
}

std::vector<std::string> split_key(const std::string& key, const YamlPosition& at) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    segments.push_back(key.substr(start, dot - start));
    if (segments.back().empty()) throw InputError(at.location(), "empty key name in '" + key + "'");
    if (dot == std::string::npos) return segments;
    start = dot + 1;
  }
}

}  // namespace

YamlDocument YamlDocument::parse(std::string_view text, const std::string& source_name) {
  YamlDocument document;
  const std::string* source = &document.sources_.emplace_back(source_name);
  LineLengthGuard(*source).feed(text);
  document.root_ = parse_tree(text, source, true);
  return document;
}

void YamlDocument::apply_override(const std::string& override_text) {
  const YamlPosition at{&sources_.emplace_back("--set " + override_text), 0, 0};
  const std::size_t equals = override_text.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError(at.location(), "expected key=value, e.g. render.spp=64");
  const std::vector<std::string> segments = split_key(override_text.substr(0, equals), at);
  const YamlNodePtr value = parse_tree(std::string_view(override_text).substr(equals + 1), at.source, false);
  root_ = with_value_at(root_, segments, 0, value, at);
}

}  // namespace rtpro
