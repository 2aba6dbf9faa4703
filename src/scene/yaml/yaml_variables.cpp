// Scene variables: `variables:` at the top of a scene gives defaults, `-D name=value` on the
// command line (an override of variables.name) replaces them, and `$name` uses them.
#include "yaml_document.h"

#include "rtpro/core/closest_match.h"
#include "yaml_keyframes.h"
#include "yaml_node_arena.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <cstdio>
#include <set>
#include <unordered_map>

namespace rtpro {

namespace {

// What substitution may produce: one value at most the longest line a scene file may hold, and all
// substituted text together at most a scene file's size. `-D v=<100 KB>` used 10,000 times in a
// line of `$v$v$v...` would make gigabytes; real scenes substitute kilobytes.
constexpr std::size_t kMaxSubstitutedValueBytes = kMaxYamlLineBytes;
constexpr std::uint64_t kMaxSubstitutedTotalBytes = std::uint64_t{64} << 20;

bool is_name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_name_char(char c) { return is_name_start(c) || (c >= '0' && c <= '9'); }

class Substitution {
 public:
  // `frame`: the frame keyframes and $frame read, instead of the variable's (motion steps).
  Substitution(const YamlNode& variables, YamlNodeArena& arena, std::optional<double> frame = std::nullopt)
      : arena_(arena) {
    if (!variables.is_mapping() && !variables.is_null())
      throw InputError(variables.at.location(),
                       "variables: expected a mapping of names to values, got " + variables.describe());
    for (const YamlEntry& entry : variables.entries()) {
      if (entry.key.empty() || !is_name_start(entry.key[0]) ||
          entry.key.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") !=
              std::string::npos)
        throw InputError(entry.key_at.location(),
                         "variables: '" + std::string(entry.key) +
                             "' is not a name (letters, digits and '_', not starting with a digit)");
      values_[std::string(entry.key)] = entry.value;
      if (entry.key_at.line == 0 && entry.key_at.source) command_line_.push_back(&entry);
    }
    if (frame) {
      YamlNode* value = arena_.node();
      value->kind = YamlNode::Kind::scalar;
      char text[40];
      std::snprintf(text, sizeof text, "%.17g", *frame);
      value->set_scalar(arena_.text(text));
      values_["frame"] = value;
    }
  }

  // A -D the scene never uses is most likely a misspelt name: refused, not ignored.
  void check_command_line_variables_used() const {
    for (const YamlEntry* entry : command_line_) {
      // --frames sets `frame` for every frame, whether or not this scene is animated.
      if (used_.count(entry->key) || entry->key == "frame") continue;
      std::string message = "the scene uses no variable '$" + std::string(entry->key) + "'";
      if (const auto near = closest_match(entry->key, unused_candidates()))
        message += "; did you mean '" + *near + "'?";
      throw InputError(entry->key_at.location(), message);
    }
  }

  // Each node is substituted once: YAML aliases share nodes, and a document of nested aliases
  // (a: [*b, *b], b: [*c, *c], ...) is a small graph that copying per path would blow up
  // exponentially (a fuzz finding: 766 bytes, 2 GB). The result shares nodes the same way.
  YamlNodePtr apply(YamlNodePtr node) const {
    if (const auto done = applied_.find(node); done != applied_.end()) return done->second;
    YamlNodePtr result = apply_once(node);
    applied_.emplace(node, result);
    return result;
  }

  // Each substituted node's original, for substituting it again at another frame.
  void record_originals(std::unordered_map<const YamlNode*, YamlNodePtr>& originals) const {
    for (const auto& [original, result] : applied_) originals.emplace(result, original);
  }

  // The frame being rendered.
  double frame_number() const { return frame(); }

 private:
  YamlNodePtr apply_once(YamlNodePtr node) const {
    switch (node->kind) {
      case YamlNode::Kind::null: return node;
      case YamlNode::Kind::scalar: return node->scalar().find('$') == std::string_view::npos ? node : substitute(*node);
      case YamlNode::Kind::sequence: {
        std::vector<YamlNodePtr> items(node->items().begin(), node->items().end());
        for (YamlNodePtr& item : items) item = apply(item);
        return arena_.with_items(*node, items);
      }
      case YamlNode::Kind::mapping: {
        std::vector<YamlEntry> entries(node->entries().begin(), node->entries().end());
        for (YamlEntry& entry : entries) entry.value = apply(entry.value);
        const YamlNodePtr copy = arena_.with_entries(*node, entries);
        return is_keyframed(*copy) ? value_at_frame(*copy, frame(), arena_) : copy;
      }
    }
    return node;
  }

  // The variable named at text[i] (just past the '$'): its name and the length of the reference.
  struct Reference {
    std::string name;
    std::size_t length = 0;  // after the '$'
  };

  static Reference reference_at(const YamlNode& node, std::size_t i) {
    const std::string_view text = node.scalar();
    if (i < text.size() && text[i] == '{') {
      const std::size_t close = text.find('}', i);
      if (close == std::string_view::npos)
        throw InputError(node.at.location(), "'${' without its closing '}' in " + node.describe());
      return {std::string(text.substr(i + 1, close - i - 1)), close - i + 1};
    }
    std::size_t end = i;
    while (end < text.size() && is_name_char(text[end])) ++end;
    if (end == i || !is_name_start(text[i]))
      throw InputError(node.at.location(),
                       "'$' must start a variable reference ($name or ${name}; '$$' for a '$') in " + node.describe());
    return {std::string(text.substr(i, end - i)), end - i};
  }

  YamlNodePtr lookup(const YamlNode& node, const std::string& name) const {
    const auto found = values_.find(name);
    if (found != values_.end()) {
      used_.insert(name);
      return found->second;
    }
    // `frame` is 1 when nothing sets it (FORMAT.md, Variables), as keyframes read it.
    if (name == "frame") {
      YamlNode* one = arena_.node(node);
      one->set_scalar(arena_.text("1"));
      return one;
    }
    std::vector<std::string> names;
    for (const auto& [defined, value] : values_) names.push_back(defined);
    std::string message = "undefined variable '$" + name + "'";
    if (const auto near = closest_match(name, names)) message += "; did you mean '$" + *near + "'?";
    throw InputError(node.at.location(), message + " (define it with -D " + name + "=VALUE or under 'variables:')");
  }

  YamlNodePtr substitute(const YamlNode& node) const {
    const std::string_view text = node.scalar();
    if (text[0] == '$' && text.size() > 1 && text[1] != '$') {
      const Reference whole = reference_at(node, 1);
      if (1 + whole.length == text.size()) return lookup(node, whole.name);
    }
    std::string result;
    for (std::size_t i = 0; i < text.size(); ++i) {
      if (text[i] != '$') {
        result += text[i];
      } else if (i + 1 < text.size() && text[i + 1] == '$') {
        result += '$';
        ++i;
      } else {
        const Reference part = reference_at(node, i + 1);
        const YamlNodePtr value = lookup(node, part.name);
        if (!value->is_scalar())
          throw InputError(node.at.location(), "'$" + part.name + "' is " + value->describe() +
                                                   ", which cannot be part of a longer text; use it alone");
        if (result.size() + value->scalar().size() > kMaxSubstitutedValueBytes)
          throw InputError(node.at.location(), "substituting '$" + part.name + "' makes a value longer than " +
                                                   std::to_string(kMaxSubstitutedValueBytes >> 20) +
                                                   " MiB (the limit on a value after variable substitution)");
        result += value->scalar();
        i += part.length;
      }
    }
    substituted_bytes_ += result.size();
    if (substituted_bytes_ > kMaxSubstitutedTotalBytes)
      throw InputError(node.at.location(), "variable substitution makes more than " +
                                               std::to_string(kMaxSubstitutedTotalBytes >> 20) +
                                               " MiB of text in all (the limit on substituted text)");
    YamlNode* copy = arena_.node(node);
    copy->set_scalar(arena_.text(result));
    return copy;
  }

  // The frame being rendered: the variable `frame` (--frames sets it for each frame), else 1.
  double frame() const {
    const auto found = values_.find("frame");
    if (found == values_.end()) return 1.0;
    used_.insert("frame");
    const YamlNode& value = *found->second;
    double number = 0;
    const std::string_view text = value.scalar();
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (!value.is_scalar() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(number))
      throw InputError(value.at.location(), "frame: expected a frame number, got " + value.describe());
    return number;
  }

  // Names the scene refers to but -D did not set: what a misspelt -D name was meant to be.
  std::vector<std::string> unused_candidates() const {
    std::vector<std::string> names;
    for (const auto& [name, value] : values_)
      if (used_.count(name) && value->at.line > 0) names.push_back(name);
    return names;
  }

  YamlNodeArena& arena_;
  std::map<std::string, YamlNodePtr> values_;
  std::vector<const YamlEntry*> command_line_;
  mutable std::set<std::string, std::less<>> used_;
  mutable std::unordered_map<const YamlNode*, YamlNodePtr> applied_;
  mutable std::uint64_t substituted_bytes_ = 0;
};

}  // namespace

void YamlDocument::resolve_variables() {
  if (!has_variables_ || !root_->is_mapping()) return;
  const YamlNode none;
  const YamlNode* variables = &none;  // keys are unique: at most one
  std::vector<YamlEntry> entries;
  for (const YamlEntry& entry : root_->entries()) {
    if (entry.key == "variables") {
      variables = entry.value;
    } else {
      entries.push_back(entry);
    }
  }
  const Substitution substitution(*variables, *arena_);
  root_ = substitution.apply(arena_->with_entries(*root_, entries));
  substitution.check_command_line_variables_used();
  variables_ = variables == &none ? nullptr : variables;
  frame_ = substitution.frame_number();
  substitution.record_originals(originals_);
}

YamlNodePtr YamlDocument::at_frame(const YamlNode& resolved, double frame) const {
  const auto original = originals_.find(&resolved);
  if (original == originals_.end()) return &resolved;  // nothing was substituted: the same at every frame
  const YamlNode none;
  const Substitution substitution(variables_ ? *variables_ : none, *arena_, frame);
  return substitution.apply(original->second);
}

}  // namespace rtpro
