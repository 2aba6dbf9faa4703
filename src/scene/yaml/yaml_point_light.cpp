#include "rtpro/scene/point_light.h"

#include "yaml_light_fields.h"

namespace rtpro {

void read_light_desc(const YamlNode& node, PointLightDesc& desc) {
  const MappingReader light(node, "point light", {"type", "name", "position", "color", "intensity"});
  desc.position = read_position(light.required("position"), light.field("position"));
  read_color_and_intensity(light, desc);
}

}  // namespace rtpro
