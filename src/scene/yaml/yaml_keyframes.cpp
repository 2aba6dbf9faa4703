#include "yaml_keyframes.h"

#include "rtpro/core/closest_match.h"
#include "yaml_node_arena.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>

namespace rtpro {

namespace {

enum class Interpolation { kLinear, kSmooth, kStep };

double parse_number(const YamlNode& node, const std::string& what) {
  double value = 0;
  const std::string_view text = node.scalar();
  const char* begin = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (!node.is_scalar() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw InputError(node.at.location(), what + ": expected a number, got " + node.describe());
  return value;
}

// A keyframe's value: a number or a list of numbers.
std::vector<double> numbers_of(const YamlNode& value, const std::string& what) {
  if (value.is_scalar()) return {parse_number(value, what)};
  if (!value.is_sequence())
    throw InputError(value.at.location(),
                     what + ": a keyframed value is a number or a list of numbers, got " + value.describe());
  std::vector<double> numbers;
  for (const YamlNodePtr& item : value.items()) numbers.push_back(parse_number(*item, what));
  return numbers;
}

Interpolation read_interpolation(const YamlNode* node) {
  if (!node) return Interpolation::kLinear;
  const std::vector<std::string> names{"linear", "smooth", "step"};
  if (node->is_scalar()) {
    if (node->scalar() == "linear") return Interpolation::kLinear;
    if (node->scalar() == "smooth") return Interpolation::kSmooth;
    if (node->scalar() == "step") return Interpolation::kStep;
  }
  throw InputError(node->at.location(),
                   "unknown interpolation " + node->describe() + suggestion(std::string(node->scalar()), names));
}

std::string number_text(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

}  // namespace

bool is_keyframed(const YamlNode& node) { return node.is_mapping() && node.find("keyframes") != nullptr; }

YamlNodePtr value_at_frame(const YamlNode& animated, double frame, YamlNodeArena& arena) {
  for (const YamlEntry& entry : animated.entries())
    if (entry.key != "keyframes" && entry.key != "interpolation")
      throw InputError(entry.key_at.location(), "unknown key '" + std::string(entry.key) + "' in an animated value" +
                                                    suggestion(std::string(entry.key), {"keyframes", "interpolation"}));
  const YamlNode& keys = *animated.find("keyframes")->value;
  const YamlEntry* interpolation_entry = animated.find("interpolation");
  const Interpolation interpolation = read_interpolation(interpolation_entry ? interpolation_entry->value : nullptr);
  if (!keys.is_mapping() || keys.entries().empty())
    throw InputError(keys.at.location(),
                     "keyframes: expected a mapping of frame numbers to values, got " + keys.describe());

  std::map<double, std::pair<std::vector<double>, const YamlNode*>> by_frame;
  for (const YamlEntry& key : keys.entries()) {
    YamlNode frame_name;
    frame_name.kind = YamlNode::Kind::scalar;
    frame_name.set_scalar(key.key);
    frame_name.at = key.key_at;
    const double key_frame = parse_number(frame_name, "keyframes: a frame number");
    std::vector<double> numbers = numbers_of(*key.value, "keyframes");
    if (!by_frame.empty() && numbers.size() != by_frame.begin()->second.first.size())
      throw InputError(key.value->at.location(), "keyframes: every key needs a value of the same shape as the first (" +
                                                     by_frame.begin()->second.second->describe() + "), got " +
                                                     key.value->describe());
    by_frame[key_frame] = {std::move(numbers), key.value};
  }

  // The keys around `frame`: the same key when the frame is on one or outside them all.
  const auto after = by_frame.lower_bound(frame);
  const auto& first = by_frame.begin()->second;
  const std::vector<double>* from = &first.first;
  const std::vector<double>* to = from;
  double t = 0.0;
  if (after == by_frame.end()) {
    from = to = &by_frame.rbegin()->second.first;
  } else if (after == by_frame.begin() || after->first == frame) {
    from = to = &after->second.first;
  } else {
    const auto before = std::prev(after);
    from = &before->second.first;
    to = &after->second.first;
    t = (frame - before->first) / (after->first - before->first);
  }
  switch (interpolation) {
    case Interpolation::kLinear: break;
    case Interpolation::kSmooth: t = t * t * (3.0 - 2.0 * t); break;
    case Interpolation::kStep: t = 0.0; break;
  }

  const auto scalar_at = [&](double value) -> YamlNodePtr {
    YamlNode* node = arena.node();
    node->kind = YamlNode::Kind::scalar;
    node->at = animated.at;
    node->set_scalar(arena.text(number_text(value)));
    return node;
  };
  std::vector<double> values(from->size());
  for (std::size_t i = 0; i < values.size(); ++i)
    values[i] = t == 0.0 ? (*from)[i] : (*from)[i] + ((*to)[i] - (*from)[i]) * t;
  if (first.second->is_scalar()) return scalar_at(values[0]);
  std::vector<YamlNodePtr> items;
  for (double value : values) items.push_back(scalar_at(value));
  YamlNode list;
  list.kind = YamlNode::Kind::sequence;
  list.at = animated.at;
  return arena.with_items(list, items);
}

}  // namespace rtpro
