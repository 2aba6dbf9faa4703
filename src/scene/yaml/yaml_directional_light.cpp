#include "rtpro/scene/directional_light.h"

#include "yaml_light_fields.h"

namespace rtpro {

void read_light_desc(const YamlNode& node, DirectionalLightDesc& desc) {
  const MappingReader light(node, "directional light", {"type", "name", "direction", "color", "intensity"});
  const YamlNode& direction = light.required("direction");
  desc.direction = read_vec3(direction, light.field("direction"));
  if (!(length(desc.direction) > 0.0f)) fail_at(direction, light.field("direction") + " must not be zero-length");
  desc.direction = normalize(desc.direction);
  read_color_and_intensity(light, desc);
}

}  // namespace rtpro
