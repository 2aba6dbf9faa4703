#pragma once
// Typed, validated reads from a YamlDocument. Every failure is an InputError at the offending
// node that names the field ("camera.fov: expected a number, got 'wide'").
#include "rtpro/core/closest_match.h"
#include "rtpro/core/vec3.h"
#include "mesh_limits.h"
#include "yaml_document.h"

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rtpro {

// Numbers further from zero than this are rejected everywhere: at float precision they mean
// nothing to a ray tracer, and far larger ones overflow (or abort Embree) once combined.
inline constexpr double kMaxSceneNumber = 1e9;
// Positions and translations may go as far as mesh vertices (kMaxAbsCoordinate, 1e16): a scene
// placed far from the origin (a georeferenced glTF) is still traceable there. Lengths such as
// radii, scale factors and edges keep kMaxSceneNumber: squared in intersection tests, a length
// beyond 1e9 leaves a float quadratic no precision, whereas a far position only shifts the origin.
inline constexpr double kMaxSceneCoordinate = kMaxAbsCoordinate;

[[noreturn]] void fail_at(const YamlPosition& at, const std::string& message);
[[noreturn]] void fail_at(const YamlNode& node, const std::string& message);

// A mapping with a fixed set of keys; constructing it rejects any other key.
class MappingReader {
 public:
  // `what` names the mapping in messages: "camera", "sphere", "material 'red'".
  MappingReader(const YamlNode& node, std::string what, std::initializer_list<std::string_view> keys)
      : MappingReader(node, std::move(what), std::span<const std::string_view>(keys.begin(), keys.size())) {}
  MappingReader(const YamlNode& node, std::string what, std::span<const std::string_view> keys);

  const YamlNode* optional(std::string_view key) const;
  const YamlNode& required(std::string_view key) const;
  // "camera.fov": the name messages use for a field.
  std::string field(std::string_view key) const { return what_ + "." + std::string(key); }
  const YamlNode& node() const { return node_; }

 private:
  const YamlNode& node_;
  std::string what_;
};

// The `type:` of a list entry (a light, a shape), one of `types`; `what` names the entry.
std::string read_entry_type(const YamlNode& entry, const std::string& what, const std::vector<std::string>& types);

// `name` is the field's name in messages.
double read_number(const YamlNode& node, const std::string& name);
// One coordinate of a position or translation: within ±kMaxSceneCoordinate.
double read_coordinate(const YamlNode& node, const std::string& name);
// A number >= 0 (weights, intensities).
float read_non_negative(const YamlNode& node, const std::string& name);
std::int64_t read_integer(const YamlNode& node, const std::string& name);
std::uint64_t read_unsigned(const YamlNode& node, const std::string& name);
std::string read_string(const YamlNode& node, const std::string& name);
Vec3 read_vec3(const YamlNode& node, const std::string& name);
// A point or translation [x, y, z], each within ±kMaxSceneCoordinate.
Vec3 read_position(const YamlNode& node, const std::string& name);
// A vec3 whose components are all >= 0 (colours).
Color read_color(const YamlNode& node, const std::string& name);
// A list of exactly `count` items, or a failure naming the expected shape.
YamlNodeList read_list(const YamlNode& node, const std::string& name, std::size_t count, std::string_view shape);

// "`name` must be a, b or c, got 'text'": the keywords in the order given.
[[noreturn]] void fail_not_one_of(const YamlNode& node, const std::string& name, const std::string& text,
                                  std::span<const std::string_view> keywords);

// The value that the keyword at `node` stands for, one of `choices`, which its failure lists in
// their order: read_keyword<Integrator>(node, "render.integrator", {{"path", Integrator::kPath}, ...}).
template <typename Value>
Value read_keyword(const YamlNode& node, const std::string& name,
                   std::initializer_list<std::pair<std::string_view, Value>> choices) {
  const std::string text = read_string(node, name);
  std::vector<std::string_view> keywords;
  for (const auto& [keyword, value] : choices) {
    if (text == keyword) return value;
    keywords.push_back(keyword);
  }
  fail_not_one_of(node, name, text, keywords);
}

}  // namespace rtpro
