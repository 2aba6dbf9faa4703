#include "rtpro/scene/spot_light.h"

#include "yaml_light_fields.h"

#include <string>

namespace rtpro {

namespace {

// A cone's half-angle off the axis in degrees: a spot light lights at most the hemisphere its
// axis points into (glTF's limit too).
float read_cone_angle(const YamlNode& node, const std::string& name) {
  const double degrees = read_number(node, name);
  if (!(degrees >= 0.0 && degrees <= 90.0))
    fail_at(node,
            name + " is the cone's half-angle off the axis: from 0 to 90 degrees, got " + std::string(node.scalar()));
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
    fail_at(light.node(),
            "spot light needs 'direction' (the axis light travels along) or 'look_at' (a point on the axis)");
  const Vec3 axis = read_position(*look_at, light.field("look_at")) - position;
  if (!(length(axis) > 0.0f))
    fail_at(*look_at, light.field("look_at") + " must differ from position: the light needs an axis to shine along");
  return normalize(axis);
}

}  // namespace

void read_light_desc(const YamlNode& node, SpotLightDesc& desc) {
  const MappingReader light(
      node, "spot light",
      {"type", "name", "position", "direction", "look_at", "color", "intensity", "inner_angle", "outer_angle"});
  desc.position = read_position(light.required("position"), light.field("position"));
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
      fail_at(*inner, light.field("inner_angle") + " (" + std::string(inner->scalar()) +
                          ") must not exceed outer_angle (" +
                          (outer ? std::string(outer->scalar()) : "45, the default") +
                          "): the light is at full intensity inside the inner cone and ends at the outer one");
  }
}

}  // namespace rtpro
