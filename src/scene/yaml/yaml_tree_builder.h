#pragma once
// The YAML document's one use of libyaml: its parse events turned into YamlNodes in an arena,
// every node with its line and column.
#include "yaml_document.h"

#include <string>
#include <string_view>

namespace rtpro {

class YamlNodeArena;

struct ParsedTree {
  YamlNodePtr root = nullptr;
  bool saw_include = false;
  bool saw_dollar = false;
};

// libyaml: an event-driven parser with positions on every event, about ten times faster than
// yaml-cpp's on scene files (third_party_notes/libyaml.md). Positions are 0 when
// `known_positions` is false (override values); a syntax error is thrown as an InputError.
ParsedTree parse_tree(std::string_view text, const std::string* source, bool known_positions, YamlNodeArena& arena);

}  // namespace rtpro
