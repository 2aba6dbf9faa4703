#include "yaml_light_linking.h"

#include <algorithm>
#include <string_view>

namespace rtpro {

namespace {

std::vector<std::string> named_lights(const std::vector<std::string>& light_names) {
  std::vector<std::string> named;
  for (const std::string& name : light_names)
    if (!name.empty()) named.push_back(name);
  return named;
}

std::uint32_t light_index(const YamlNode& node, const std::string& field, const std::vector<std::string>& light_names) {
  const std::string name = read_string(node, field);
  const auto found = std::find(light_names.begin(), light_names.end(), name);
  if (!name.empty() && found != light_names.end()) return static_cast<std::uint32_t>(found - light_names.begin());
  const std::vector<std::string> named = named_lights(light_names);
  fail_at(node, field + ": unknown light '" + name + "'" +
                    (named.empty() ? "; give the light a name (lights: - {type: ..., name: " + name + ", ...})"
                                   : suggestion(name, named)));
}

// The two spellings of a list: the only lights that count, or the lights left out.
struct ListKeys {
  std::string_view only, all_but;
};
constexpr ListKeys kIlluminationKeys{"illuminated_by", "not_illuminated_by"};
constexpr ListKeys kShadowKeys{"shadows_from", "no_shadows_from"};

// {only: [names]} or {all_but: [names]} in `keys`' spelling: exactly one of the two.
LightListDesc read_light_list(const YamlNode& node, const std::string& what, const ListKeys& keys,
                              const std::vector<std::string>& light_names) {
  const MappingReader list(node, what, {keys.only, keys.all_but});
  const YamlNode* only = list.optional(keys.only);
  const YamlNode* all_but = list.optional(keys.all_but);
  if (only && all_but)
    fail_at(*all_but, what + ": give " + std::string(keys.only) + " (only these lights) or " +
                          std::string(keys.all_but) + " (every light but these), not both");
  if (!only && !all_but)
    fail_at(node, what + " needs " + std::string(keys.only) + ": [light names] (only these) or " +
                      std::string(keys.all_but) + ": [light names] (every light but these)");
  const YamlNode& names = only ? *only : *all_but;
  const std::string field = list.field(only ? keys.only : keys.all_but);
  if (!names.is_sequence()) fail_at(names, field + ": expected a list of light names, got " + names.describe());
  LightListDesc desc;
  desc.include = only != nullptr;
  for (const YamlNodePtr& name : names.items()) {
    const std::uint32_t index = light_index(*name, field, light_names);
    if (std::find(desc.lights.begin(), desc.lights.end(), index) != desc.lights.end())
      fail_at(*name, field + ": light '" + light_names[index] + "' is listed twice");
    desc.lights.push_back(index);
  }
  return desc;
}

}  // namespace

std::optional<LightLinkingDesc> read_light_linking(const MappingReader& entry,
                                                   const std::vector<std::string>& light_names) {
  const YamlNode* light = entry.optional(kLightLinkingKey);
  const YamlNode* shadow = entry.optional(kShadowLinkingKey);
  if (!light && !shadow) return std::nullopt;
  LightLinkingDesc desc;
  if (light) desc.illumination = read_light_list(*light, entry.field(kLightLinkingKey), kIlluminationKeys, light_names);
  if (shadow) desc.shadows = read_light_list(*shadow, entry.field(kShadowLinkingKey), kShadowKeys, light_names);
  return desc;
}

}  // namespace rtpro
