#include "yaml_reader.h"

#include "rtpro/core/closest_match.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace rtpro {

void fail_at(const YamlPosition& at, const std::string& message) { throw InputError(at.location(), message); }

void fail_at(const YamlNode& node, const std::string& message) { fail_at(node.at, message); }

namespace {

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
  const std::string_view text = without_plus(scalar_or_fail(node, name, expected).scalar());
  Integer value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || text.empty())
    fail_at(node, name + ": expected " + std::string(expected) + ", got " + node.describe());
  if (error == std::errc::result_out_of_range)
    fail_at(node, name + ": " + std::string(node.scalar()) + " is out of range");
  return value;
}

}  // namespace

MappingReader::MappingReader(const YamlNode& node, std::string what, std::span<const std::string_view> keys)
    : node_(node), what_(std::move(what)) {
  if (!node.is_mapping()) fail_at(node, what_ + ": expected a mapping, got " + node.describe());
  for (const YamlEntry& entry : node.entries()) {
    if (std::find(keys.begin(), keys.end(), entry.key) == keys.end()) {
      fail_at(entry.key_at, "unknown key '" + std::string(entry.key) + "' in " + what_ +
                                suggestion(entry.key, std::vector<std::string>(keys.begin(), keys.end())));
    }
  }
}

const YamlNode* MappingReader::optional(std::string_view key) const {
  const YamlEntry* entry = node_.find(key);
  return entry ? entry->value : nullptr;
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

namespace {

// A number within ±bound; `bound_text` is how messages show the bound.
double read_bounded(const YamlNode& node, const std::string& name, double bound, const char* bound_text) {
  const std::string_view text = without_plus(scalar_or_fail(node, name, "a number").scalar());
  if (is_yaml_special_float(text))
    fail_at(node, name + ": expected a finite number, got '" + std::string(node.scalar()) + "'");
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size() || text.empty())
    fail_at(node, name + ": expected a number, got " + node.describe());
  if (error == std::errc::result_out_of_range || !std::isfinite(value) || std::fabs(value) > bound) {
    fail_at(node, name + ": " + std::string(node.scalar()) + " is out of range (numbers must be finite and within ±" +
                      bound_text + ")");
  }
  return value;
}

}  // namespace

double read_number(const YamlNode& node, const std::string& name) {
  return read_bounded(node, name, kMaxSceneNumber, "1e9");
}

double read_coordinate(const YamlNode& node, const std::string& name) {
  return read_bounded(node, name, kMaxSceneCoordinate, "1e16 for positions");
}

float read_non_negative(const YamlNode& node, const std::string& name) {
  const double value = read_number(node, name);
  if (value < 0.0) fail_at(node, name + " must be >= 0, got " + std::string(node.scalar()));
  return static_cast<float>(value);
}

std::int64_t read_integer(const YamlNode& node, const std::string& name) {
  return parse_integer<std::int64_t>(node, name, "an integer");
}

std::uint64_t read_unsigned(const YamlNode& node, const std::string& name) {
  return parse_integer<std::uint64_t>(node, name, "a non-negative integer");
}

std::string read_string(const YamlNode& node, const std::string& name) {
  if (!node.is_scalar() || node.scalar().empty()) fail_at(node, name + ": expected a name, got " + node.describe());
  return std::string(node.scalar());
}

void fail_not_one_of(const YamlNode& node, const std::string& name, const std::string& text,
                     std::span<const std::string_view> keywords) {
  std::string listed;
  for (std::size_t k = 0; k < keywords.size(); ++k)
    listed += (k == 0 ? "" : (k + 1 == keywords.size() ? " or " : ", ")) + std::string(keywords[k]);
  fail_at(node, name + " must be " + listed + ", got '" + text + "'");
}

YamlNodeList read_list(const YamlNode& node, const std::string& name, std::size_t count, std::string_view shape) {
  if (!node.is_sequence() || node.items().size() != count)
    fail_at(node, name + ": expected " + std::string(shape) + ", got " + node.describe());
  return node.items();
}

namespace {

using NumberReader = double (*)(const YamlNode&, const std::string&);

Vec3 read_triple(const YamlNode& node, const std::string& name, NumberReader read) {
  const auto& items = read_list(node, name, 3, "a list of 3 numbers [x, y, z]");
  return Vec3(static_cast<float>(read(*items[0], name)), static_cast<float>(read(*items[1], name)),
              static_cast<float>(read(*items[2], name)));
}

}  // namespace

Vec3 read_vec3(const YamlNode& node, const std::string& name) { return read_triple(node, name, read_number); }

Vec3 read_position(const YamlNode& node, const std::string& name) { return read_triple(node, name, read_coordinate); }

namespace {

bool is_whole_number_text(std::string_view text) {
  return !text.empty() && text.find_first_not_of("+0123456789") == std::string_view::npos;
}

double whole_number(std::string_view text) { return std::strtod(std::string(text).c_str(), nullptr); }

// [255, 128, 0] is an 8-bit colour picker's value, not a linear colour 255 times "full": a
// material would reflect 255 times the light it receives. Whole numbers above 1, all at most
// 255, are refused with the linear value; HDR colours are written with a decimal point, and a
// brighter light raises its intensity.
void reject_8bit_color(const YamlNode& node, YamlNodeList items, const std::string& name) {
  double largest = 0.0;
  for (const YamlNodePtr& item : items) {
    if (!is_whole_number_text(item->scalar())) return;
    largest = std::max(largest, whole_number(item->scalar()));
  }
  if (largest <= 1.0 || largest > 255.0) return;
  std::string linear;
  for (const YamlNodePtr& item : items) {
    char text[32];
    const double encoded = whole_number(item->scalar()) / 255.0;
    const double decoded = encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
    std::snprintf(text, sizeof text, "%.3g", decoded);
    linear += (linear.empty() ? "" : ", ") + std::string(text);
  }
  fail_at(node, name + ": [" + std::string(items[0]->scalar()) + ", " + std::string(items[1]->scalar()) + ", " +
                    std::string(items[2]->scalar()) +
                    "] looks like 8-bit sRGB values; colours are linear with 1 as full: that colour is [" + linear +
                    "] (for a brighter light raise its intensity; write 2.0 for a deliberate value above 1)");
}

}  // namespace

Color read_color(const YamlNode& node, const std::string& name) {
  const auto& items = read_list(node, name, 3, "a colour [r, g, b]");
  Color color;
  for (int i = 0; i < 3; ++i) {
    const double component = read_number(*items[i], name);
    if (component < 0.0)
      fail_at(*items[i], name + ": colour components must be >= 0, got " + std::string(items[i]->scalar()));
    color[i] = static_cast<float>(component);
  }
  reject_8bit_color(node, items, name);
  return color;
}

}  // namespace rtpro
