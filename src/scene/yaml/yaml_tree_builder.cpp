#include "yaml_tree_builder.h"

#include "yaml_node_arena.h"

#include <yaml.h>

#include <algorithm>
#include <cstring>
#include <new>
#include <optional>
#include <unordered_map>

namespace rtpro {

namespace {

// Plain scalars that YAML reads as null; libyaml leaves that to its caller.
bool is_null_scalar(const yaml_event_t& event) {
  if (event.data.scalar.style != YAML_PLAIN_SCALAR_STYLE) return false;
  const std::string_view text(reinterpret_cast<const char*>(event.data.scalar.value), event.data.scalar.length);
  return text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL";
}

std::string_view text_of(const yaml_char_t* text) {
  return text ? std::string_view(reinterpret_cast<const char*>(text)) : std::string_view();
}

// Turns libyaml's parse events into YamlNodes. Positions are libyaml's 0-based marks made
// 1-based, or 0 when `known_positions` is false (override values).
class TreeBuilder {
 public:
  TreeBuilder(const std::string* source, bool known_positions, YamlNodeArena& arena)
      : source_(source), known_positions_(known_positions), arena_(arena) {}

  YamlNodePtr root() { return root_ ? root_ : null_node(YamlPosition{source_, 0, 0}); }
  bool saw_include() const { return saw_include_; }
  bool saw_dollar() const { return saw_dollar_; }

  void handle(const yaml_event_t& event) {
    const yaml_mark_t& mark = event.start_mark;
    switch (event.type) {
      case YAML_DOCUMENT_START_EVENT:
        if (++documents_ > 1) fail(mark, "more than one YAML document ('---'); a scene is one document");
        break;
      case YAML_ALIAS_EVENT: {
        const std::string anchor(text_of(event.data.alias.anchor));
        const auto found = anchors_.find(anchor);
        if (found != anchors_.end()) {
          complete(found->second, {});
        } else if (is_open(anchor)) {
          fail(mark, "alias refers to a node that contains it");
        } else {
          fail(mark, "alias '*" + anchor + "' refers to no anchor '&" + anchor + "' before it");
        }
        break;
      }
      case YAML_SCALAR_EVENT: {
        reject_tag(mark, event.data.scalar.tag);
        const std::string_view anchor = text_of(event.data.scalar.anchor);
        const std::string_view value(reinterpret_cast<const char*>(event.data.scalar.value), event.data.scalar.length);
        if (value.find('$') != std::string_view::npos) saw_dollar_ = true;
        if (is_null_scalar(event)) {
          complete(null_node(position(mark)), anchor);
        } else if (anchor.empty() && expects_key()) {
          add_key(value, position(mark));  // most scalars are keys: no node for them
        } else {
          YamlNode* node = arena_.node();
          node->kind = YamlNode::Kind::scalar;
          node->at = position(mark);
          node->set_scalar(arena_.text(value));
          node->plain = event.data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
          complete(node, anchor);
        }
        break;
      }
      case YAML_SEQUENCE_START_EVENT:
        reject_tag(mark, event.data.sequence_start.tag);
        open(mark, text_of(event.data.sequence_start.anchor), YamlNode::Kind::sequence);
        break;
      case YAML_MAPPING_START_EVENT:
        reject_tag(mark, event.data.mapping_start.tag);
        open(mark, text_of(event.data.mapping_start.anchor), YamlNode::Kind::mapping);
        break;
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT: close(); break;
      case YAML_NO_EVENT:
      case YAML_STREAM_START_EVENT:
      case YAML_STREAM_END_EVENT:
      case YAML_DOCUMENT_END_EVENT: break;
    }
  }

  YamlPosition position(const yaml_mark_t& mark) const {
    if (!known_positions_) return {source_, 0, 0};
    return {source_, static_cast<int>(mark.line) + 1, static_cast<int>(mark.column) + 1};
  }

 private:
  // A sequence or mapping being read. Its children gather in `item_list`/`entry_list`, which
  // keep their capacity from one node to the next at the same depth, and are copied into the
  // arena, sized exactly, when it closes.
  struct Open {
    YamlNode* node = nullptr;
    std::string anchor;
    std::vector<YamlNodePtr> item_list;
    std::vector<YamlEntry> entry_list;
    bool pending = false;  // entry_list.back() is a key waiting for its value
  };

  [[noreturn]] void fail(const yaml_mark_t& mark, const std::string& message) const {
    throw InputError(position(mark).location(), message);
  }

  void reject_tag(const yaml_mark_t& mark, const yaml_char_t* tag) const {
    if (tag) fail(mark, "YAML tags ('" + std::string(text_of(tag)) + "') are not used in rtpro scenes");
  }

  bool is_open(const std::string& anchor) const {
    for (std::size_t level = 0; level < depth_; ++level)
      if (levels_[level].anchor == anchor) return true;
    return false;
  }

  YamlNodePtr null_node(YamlPosition at) {
    YamlNode* node = arena_.node();
    node->at = at;
    return node;
  }

  bool expects_key() const {
    return depth_ > 0 && levels_[depth_ - 1].node->is_mapping() && !levels_[depth_ - 1].pending;
  }

  void add_key(std::string_view key, const YamlPosition& at) {
    Open& mapping = levels_[depth_ - 1];
    for (const YamlEntry& first : mapping.entry_list) {
      if (first.key != key) continue;
      std::string message = "duplicate key '" + std::string(key) + "'";
      if (first.key_at.line > 0) message += " (first given at line " + std::to_string(first.key_at.line) + ")";
      throw InputError(at.location(), message);
    }
    if (key == "include") saw_include_ = true;
    if (key == "variables" || key == "keyframes") saw_dollar_ = true;
    mapping.entry_list.push_back(YamlEntry{arena_.text(key), at, nullptr});
    mapping.pending = true;
  }

  void open(const yaml_mark_t& mark, std::string_view anchor, YamlNode::Kind kind) {
    if (depth_ >= static_cast<std::size_t>(kMaxYamlNesting))
      fail(mark, "YAML nesting deeper than " + std::to_string(kMaxYamlNesting) + " levels");
    if (levels_.size() == depth_) levels_.emplace_back();
    Open& level = levels_[depth_++];
    level.node = arena_.node();
    level.node->kind = kind;
    level.node->at = position(mark);
    level.anchor = anchor;
    level.item_list.clear();
    level.entry_list.clear();
    level.pending = false;
  }

  void close() {
    Open& level = levels_[--depth_];
    if (level.node->is_sequence()) {
      level.node->set_items(arena_.list(level.item_list));
    } else {
      level.node->set_entries(arena_.list(level.entry_list));
    }
    level.item_list.clear();
    level.entry_list.clear();
    complete(level.node, level.anchor);
  }

  void complete(YamlNodePtr node, std::string_view anchor) {
    if (!anchor.empty()) anchors_[std::string(anchor)] = node;
    if (depth_ == 0) {
      root_ = node;
      return;
    }
    Open& parent = levels_[depth_ - 1];
    if (parent.node->is_sequence()) {
      parent.item_list.push_back(node);
    } else if (!parent.pending) {
      // Keys that are plain scalars never get here (add_key); anything else is not a name.
      if (!node->is_scalar())
        throw InputError(node->at.location(), "a mapping key must be a name, got " + node->describe());
      add_key(node->scalar(), node->at);
    } else {
      YamlEntry& entry = parent.entry_list.back();
      parent.pending = false;
      // An empty value is reported at its key, the place a reader looks for it.
      entry.value = node->is_null() && anchor.empty() ? null_node(entry.key_at) : node;
    }
  }

  const std::string* source_;
  bool known_positions_;
  bool saw_include_ = false;
  bool saw_dollar_ = false;
  YamlNodeArena& arena_;
  int documents_ = 0;
  std::vector<Open> levels_;  // levels_[0, depth_) are open; the rest keep their capacity
  std::size_t depth_ = 0;
  std::unordered_map<std::string, YamlNodePtr> anchors_;
  YamlNodePtr root_ = nullptr;
};

// libyaml's reader errors (bad UTF-8, control characters) carry a byte offset, not a mark.
yaml_mark_t mark_of_offset(std::string_view text, std::size_t offset) {
  yaml_mark_t mark{};
  mark.index = std::min(offset, text.size());
  for (std::size_t i = 0; i < mark.index; ++i) {
    if (text[i] == '\n') {
      ++mark.line;
      mark.column = 0;
    } else {
      ++mark.column;
    }
  }
  return mark;
}

// The first tab in the indentation of the line holding `mark`, if any. libyaml reports one as
// "found character that cannot start any token" (or a mapping error a line later), which does not
// say what to change; YAML allows only spaces there.
std::optional<yaml_mark_t> indentation_tab(std::string_view text, const yaml_mark_t& mark) {
  const std::size_t at = std::min(mark.index, text.size());
  std::size_t i = 0;  // the start of the line
  if (const std::size_t newline = at == 0 ? std::string_view::npos : text.rfind('\n', at - 1);
      newline != std::string_view::npos)
    i = newline + 1;
  yaml_mark_t tab = mark;
  tab.column = 0;
  for (; i < text.size() && (text[i] == ' ' || text[i] == '\t'); ++i, ++tab.column) {
    if (text[i] == '\t') {
      tab.index = i;
      return tab;
    }
  }
  return std::nullopt;
}

[[noreturn]] void throw_syntax_error(const yaml_parser_t& parser, std::string_view text, const TreeBuilder& builder) {
  if (parser.error == YAML_MEMORY_ERROR) throw std::bad_alloc();
  const yaml_mark_t mark =
      parser.error == YAML_READER_ERROR ? mark_of_offset(text, parser.problem_offset) : parser.problem_mark;
  if (const std::optional<yaml_mark_t> tab = indentation_tab(text, mark))
    throw InputError(builder.position(*tab).location(),
                     "YAML syntax error: tab characters are not allowed in YAML indentation (indent with spaces)");
  std::string message = std::string("YAML syntax error: ") + (parser.problem ? parser.problem : "unreadable YAML");
  if (parser.context) {
    const YamlPosition context_at = builder.position(parser.context_mark);
    message += std::string(" (") + parser.context;
    if (context_at.line > 0)
      message +=
          " that starts at line " + std::to_string(context_at.line) + ", column " + std::to_string(context_at.column);
    message += ")";
  }
  throw InputError(builder.position(mark).location(), message);
}

}  // namespace

ParsedTree parse_tree(std::string_view text, const std::string* source, bool known_positions, YamlNodeArena& arena) {
  struct Parser {
    yaml_parser_t parser;
    Parser() {
      if (!yaml_parser_initialize(&parser)) throw std::bad_alloc();
    }
    ~Parser() { yaml_parser_delete(&parser); }
  } yaml;
  struct Event {
    yaml_event_t event{};
    ~Event() { yaml_event_delete(&event); }
  };
  yaml_parser_set_input_string(&yaml.parser, reinterpret_cast<const unsigned char*>(text.data()), text.size());
  TreeBuilder builder(source, known_positions, arena);
  while (true) {
    Event next;
    if (!yaml_parser_parse(&yaml.parser, &next.event)) throw_syntax_error(yaml.parser, text, builder);
    builder.handle(next.event);
    if (next.event.type == YAML_STREAM_END_EVENT) break;
  }
  return {builder.root(), builder.saw_include(), builder.saw_dollar()};
}

}  // namespace rtpro
