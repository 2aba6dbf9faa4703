#include "yaml_lights.h"

#include "yaml_reader.h"

#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rtpro {

namespace {

// What a scene file calls each kind of light (its `type:`) and how it reads one are the kind's own
// (scene/point_light.h and its neighbours): both visit every alternative of LightDesc, so a new
// kind of light does not compile until it has a name and a reader.
const char* light_type(const LightDesc& kind) {
  return std::visit([](const auto& desc) { return light_type_name(desc); }, kind);
}

LightDesc read_light_of_kind(const YamlNode& node, LightDesc kind) {
  std::visit([&](auto& desc) { read_light_desc(node, desc); }, kind);
  return kind;
}

// One light of every kind, in LightDesc's order.
template <std::size_t... I>
std::vector<LightDesc> every_light_kind(std::index_sequence<I...>) {
  return {LightDesc(std::in_place_index<I>)...};
}

LightDesc read_light(const YamlNode& node) {
  static const std::vector<LightDesc> kinds =
      every_light_kind(std::make_index_sequence<std::variant_size_v<LightDesc>>());
  std::vector<std::string> types;
  for (const LightDesc& kind : kinds) types.push_back(light_type(kind));
  const std::string type = read_entry_type(node, "light", types);
  for (const LightDesc& kind : kinds)
    if (type == light_type(kind)) return read_light_of_kind(node, kind);
  fail_at(node, "unknown light type '" + type + "'");  // read_entry_type accepts only the types above
}

// `name:`, which light linking refers to (FORMAT.md, "Light linking"): unique among the lights.
std::string read_light_name(const YamlNode& node, const std::vector<std::string>& earlier) {
  const YamlEntry* entry = node.is_mapping() ? node.find("name") : nullptr;
  if (!entry) return {};
  const std::string name = read_string(*entry->value, "light.name");
  if (name.empty()) fail_at(*entry->value, "light.name must not be empty");
  for (const std::string& other : earlier)
    if (other == name) fail_at(*entry->value, "light.name: another light is already named '" + name + "'");
  return name;
}

}  // namespace

void read_lights(const YamlNode* node, std::vector<LightDesc>& lights, std::vector<std::string>& names) {
  lights.clear();
  names.clear();
  if (!node || node->is_null()) return;
  if (!node->is_sequence()) fail_at(*node, "lights: expected a list of lights, got " + node->describe());
  for (const YamlNodePtr& light : node->items()) {
    lights.push_back(read_light(*light));
    names.push_back(read_light_name(*light, names));
  }
}

}  // namespace rtpro
