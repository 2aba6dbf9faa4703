#include "yaml_lights.h"

#include "yaml_reader.h"
#include "rtpro/core/overloaded.h"

#include <cmath>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace rtpro {

namespace {

// `color` and `intensity`, which every kind of light has.
template <typename Desc>
void read_color_and_intensity(const MappingReader& light, Desc& desc) {
  if (const YamlNode* color = light.optional("color")) desc.color = read_color(*color, light.field("color"));
  if (const YamlNode* intensity = light.optional("intensity"))
    desc.intensity = read_non_negative(*intensity, light.field("intensity"));
}

// Shadow rays per axis of an area light: samples² per light per shading point.
int read_light_samples(const MappingReader& light, int fallback) {
  const YamlNode* node = light.optional("samples");
  if (!node) return fallback;
  const double n = read_number(*node, light.field("samples"));
  if (!(n >= 1.0 && n <= 64.0) || n != std::floor(n))
    fail_at(*node, light.field("samples") + " is shadow rays per axis (samples² per point): a whole number from 1 to 64, got " +
                       std::string(node->scalar()));
  return static_cast<int>(n);
}

PointLightDesc read_point_light(const YamlNode& node) {
  const MappingReader light(node, "point light", {"type", "name", "position", "color", "intensity"});
  PointLightDesc desc;
  desc.position = read_vec3(light.required("position"), light.field("position"));
  read_color_and_intensity(light, desc);
  return desc;
}

// A cone's half-angle off the axis in degrees: a spot light lights at most the hemisphere its
// axis points into (glTF's limit too).
float read_cone_angle(const YamlNode& node, const std::string& name) {
  const double degrees = read_number(node, name);
  if (!(degrees >= 0.0 && degrees <= 90.0))
    fail_at(node, name + " is the cone's half-angle off the axis: from 0 to 90 degrees, got " + std::string(node.scalar()));
  return static_cast<float>(degrees);
}

// The unit axis, from `direction` or from `look_at` (a point on it): exactly one of the two.
Vec3 read_spot_axis(const MappingReader& light, const Vec3& position) {
  const YamlNode* direction = light.optional("direction");
  const YamlNode* look_at = light.optional("look_at");
  if (direction && look_at)
    fail_at(*look_at, light.field("look_at") + ": give the axis by direction or by look_at, not both");
  if (direction) {
    const Vec3 axis = read_vec3(*direction, light.field("direction"));
    if (!(length(axis) > 0.0f)) fail_at(*direction, light.field("direction") + " must not be zero-length");
    return normalize(axis);
  }
  if (!look_at)
    fail_at(light.node(), "spot light needs 'direction' (the axis light travels along) or 'look_at' (a point on the axis)");
  const Vec3 axis = read_vec3(*look_at, light.field("look_at")) - position;
  if (!(length(axis) > 0.0f))
    fail_at(*look_at, light.field("look_at") + " must differ from position: the light needs an axis to shine along");
  return normalize(axis);
}

SpotLightDesc read_spot_light(const YamlNode& node) {
  const MappingReader light(node, "spot light",
                            {"type", "name", "position", "direction", "look_at", "color", "intensity", "inner_angle", "outer_angle"});
  SpotLightDesc desc;
  desc.position = read_vec3(light.required("position"), light.field("position"));
  desc.direction = read_spot_axis(light, desc.position);
  read_color_and_intensity(light, desc);
  const YamlNode* outer = light.optional("outer_angle");
  if (outer) {
    desc.outer_angle = read_cone_angle(*outer, light.field("outer_angle"));
    if (!(desc.outer_angle > 0.0f))
      fail_at(*outer, light.field("outer_angle") + " must be > 0: a cone of no width lights nothing");
  }
  if (const YamlNode* inner = light.optional("inner_angle")) {
    desc.inner_angle = read_cone_angle(*inner, light.field("inner_angle"));
    if (desc.inner_angle > desc.outer_angle)
      fail_at(*inner, light.field("inner_angle") + " (" + std::string(inner->scalar()) + ") must not exceed outer_angle (" +
                          (outer ? std::string(outer->scalar()) : "45, the default") +
                          "): the light is at full intensity inside the inner cone and ends at the outer one");
  }
  return desc;
}

DirectionalLightDesc read_directional_light(const YamlNode& node) {
  const MappingReader light(node, "directional light", {"type", "name", "direction", "color", "intensity"});
  DirectionalLightDesc desc;
  const YamlNode& direction = light.required("direction");
  desc.direction = read_vec3(direction, light.field("direction"));
  if (!(length(desc.direction) > 0.0f)) fail_at(direction, light.field("direction") + " must not be zero-length");
  desc.direction = normalize(desc.direction);
  read_color_and_intensity(light, desc);
  return desc;
}

SphereLightDesc read_sphere_light(const YamlNode& node) {
  const MappingReader light(node, "sphere light", {"type", "name", "center", "radius", "color", "intensity", "samples"});
  SphereLightDesc desc;
  desc.center = read_vec3(light.required("center"), light.field("center"));
  const YamlNode& radius = light.required("radius");
  desc.radius = static_cast<float>(read_number(radius, light.field("radius")));
  if (!(desc.radius > 0.0f)) fail_at(radius, light.field("radius") + " must be positive, got " + std::string(radius.scalar()));
  read_color_and_intensity(light, desc);
  desc.samples = read_light_samples(light, desc.samples);
  return desc;
}

QuadLightDesc read_quad_light(const YamlNode& node) {
  const MappingReader light(node, "quad light", {"type", "name", "position", "edge1", "edge2", "color", "intensity", "samples"});
  QuadLightDesc desc;
  desc.position = read_vec3(light.required("position"), light.field("position"));
  const YamlNode& edge1 = light.required("edge1");
  const YamlNode& edge2 = light.required("edge2");
  desc.edge1 = read_vec3(edge1, light.field("edge1"));
  desc.edge2 = read_vec3(edge2, light.field("edge2"));
  const Vec3 n = cross(desc.edge1, desc.edge2);
  if (!(length(n) > 1e-12f * length(desc.edge1) * length(desc.edge2)) || !(length(n) > 0.0f))
    fail_at(edge2, light.field("edge2") + " must not be zero or parallel to edge1: the quad has no area");
  read_color_and_intensity(light, desc);
  desc.samples = read_light_samples(light, desc.samples);
  return desc;
}

// What a scene file calls each kind of light (its `type:`) and how it reads one: both visit every
// alternative of LightDesc, so a new kind of light does not compile until it has a name and a reader.
const char* light_type(const LightDesc& kind) {
  return std::visit(Overloaded{[](const PointLightDesc&) { return "point"; },
                               [](const SpotLightDesc&) { return "spot"; },
                               [](const DirectionalLightDesc&) { return "directional"; },
                               [](const SphereLightDesc&) { return "sphere"; },
                               [](const QuadLightDesc&) { return "quad"; }},
                    kind);
}

LightDesc read_light_of_kind(const YamlNode& node, const LightDesc& kind) {
  return std::visit(Overloaded{[&](const PointLightDesc&) -> LightDesc { return read_point_light(node); },
                               [&](const SpotLightDesc&) -> LightDesc { return read_spot_light(node); },
                               [&](const DirectionalLightDesc&) -> LightDesc { return read_directional_light(node); },
                               [&](const SphereLightDesc&) -> LightDesc { return read_sphere_light(node); },
                               [&](const QuadLightDesc&) -> LightDesc { return read_quad_light(node); }},
                    kind);
}

// One light of every kind, in LightDesc's order.
template <std::size_t... I>
std::vector<LightDesc> every_light_kind(std::index_sequence<I...>) {
  return {LightDesc(std::in_place_index<I>)...};
}

LightDesc read_light(const YamlNode& node) {
  static const std::vector<LightDesc> kinds = every_light_kind(std::make_index_sequence<std::variant_size_v<LightDesc>>());
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
