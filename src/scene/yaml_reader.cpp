#include "yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace rtpro {

void fail_at(const YamlPosition& at, const std::string& message) { throw InputError(at.location(), message); }

void fail_at(const YamlNode& node, const std::string& message) { fail_at(node.at, message); }

namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

// Optimal string alignment distance: insertions, deletions, substitutions and adjacent swaps
// ("resolutoin") each cost one; case is ignored.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

bool is_yaml_special_float(std::string_view text) {
  if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.remove_prefix(1);
  for (std::string_view special : {".inf", ".Inf", ".INF", ".nan", ".NaN", ".NAN", "inf", "nan", "infinity"})
    if (text == special) return true;
  return false;
}

std::string_view without_plus(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-') text.remove_prefix(1);
  return text;
}

const YamlNode& scalar_or_fail(const YamlNode& node, const std::string& name, std::string_view expected) {
  if (!node.is_scalar() || !node.plain)
    fail_at(node, name + ": expected " + std::string(expected) + ", got " + node.describe());
  return node;
}

template <typename Integer>
Integer parse_integer(const YamlNode& node, const std::string& name, std::string_view expected) {
  const std::string_view text = without_plus(scalar_or_fail(node, name, expected).scalar);
  Integer value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || text.empty())
    fail_at(node, name + ": expected " + std::string(expected) + ", got " + node.describe());
  if (error == std::errc::result_out_of_range) fail_at(node, name + ": " + node.scalar + " is out of range");
  return value;
}

}  // namespace

std::optional<std::string> closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  const std::size_t tolerance = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string> best;
  std::size_t best_distance = tolerance + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t distance = edit_distance(word, candidate);
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

std::string suggestion(std::string_view word, const std::vector<std::string>& candidates) {
  if (const auto near = closest_match(word, candidates)) return "; did you mean '" + *near + "'?";
  if (candidates.empty()) return "";
  constexpr std::size_t kListed = 12;
  std::string text = "; expected one of: ";
  for (std::size_t i = 0; i < std::min(kListed, candidates.size()); ++i) text += (i ? ", " : "") + candidates[i];
  if (candidates.size() > kListed) text += ", ... (" + std::to_string(candidates.size()) + " in all)";
  return text;
}

MappingReader::MappingReader(const YamlNode& node, std::string what, std::vector<std::string> keys)
    : node_(node), what_(std::move(what)) {
  if (!node.is_mapping()) fail_at(node, what_ + ": expected a mapping, got " + node.describe());
  for (const YamlEntry& entry : node.entries) {
    if (std::find(keys.begin(), keys.end(), entry.key) == keys.end())
      fail_at(entry.key_at, "unknown key '" + entry.key + "' in " + what_ + suggestion(entry.key, keys));
  }
}

const YamlNode* MappingReader::optional(std::string_view key) const {
  const YamlEntry* entry = node_.find(key);
  return entry ? entry->value.get() : nullptr;
}

const YamlNode& MappingReader::required(std::string_view key) const {
  const YamlNode* value = optional(key);
  if (!value) fail_at(node_, what_ + " is missing the required key '" + std::string(key) + "'");
  return *value;
}

std::string read_entry_type(const YamlNode& entry, const std::string& what, const std::vector<std::string>& types) {
  if (!entry.is_mapping()) fail_at(entry, what + ": expected a mapping with a 'type', got " + entry.describe());
  const YamlEntry* type = entry.find("type");
  if (!type) {
    std::string listed;
    for (const std::string& name : types) listed += (listed.empty() ? "" : ", ") + name;
    fail_at(entry, what + " is missing the required key 'type' (one of: " + listed + ")");
  }
  const std::string name = read_string(*type->value, what + ".type");
  if (std::find(types.begin(), types.end(), name) == types.end())
    fail_at(*type->value, "unknown " + what + " type '" + name + "'" + suggestion(name, types));
  return name;
}

double read_number(const YamlNode& node, const std::string& name) {
  const std::string_view text = without_plus(scalar_or_fail(node, name, "a number").scalar);
  if (is_yaml_special_float(text)) fail_at(node, name + ": expected a finite number, got '" + node.scalar + "'");
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || text.empty())
    fail_at(node, name + ": expected a number, got " + node.describe());
  if (error == std::errc::result_out_of_range || !std::isfinite(value) || std::fabs(value) > kMaxSceneNumber) {
    fail_at(node, name + ": " + node.scalar + " is out of range (numbers must be finite and within ±1e9)");
  }
  return value;
}

std::int64_t read_integer(const YamlNode& node, const std::string& name) {
  return parse_integer<std::int64_t>(node, name, "an integer");
}

std::uint64_t read_unsigned(const YamlNode& node, const std::string& name) {
  return parse_integer<std::uint64_t>(node, name, "a non-negative integer");
}

std::string read_string(const YamlNode& node, const std::string& name) {
  if (!node.is_scalar() || node.scalar.empty()) fail_at(node, name + ": expected a name, got " + node.describe());
  return node.scalar;
}

const YamlNodeList& read_list(const YamlNode& node, const std::string& name, std::size_t count,
                                          std::string_view shape) {
  if (!node.is_sequence() || node.items.size() != count)
    fail_at(node, name + ": expected " + std::string(shape) + ", got " + node.describe());
  return node.items;
}

Vec3 read_vec3(const YamlNode& node, const std::string& name) {
  const auto& items = read_list(node, name, 3, "a list of 3 numbers [x, y, z]");
  return Vec3(static_cast<float>(read_number(*items[0], name)), static_cast<float>(read_number(*items[1], name)),
              static_cast<float>(read_number(*items[2], name)));
}

Color read_color(const YamlNode& node, const std::string& name) {
  const auto& items = read_list(node, name, 3, "a colour [r, g, b]");
  Color color;
  for (int i = 0; i < 3; ++i) {
    const double component = read_number(*items[i], name);
    if (component < 0.0) fail_at(*items[i], name + ": colour components must be >= 0, got " + items[i]->scalar);
    color[i] = static_cast<float>(component);
  }
  return color;
}

}  // namespace rtpro
