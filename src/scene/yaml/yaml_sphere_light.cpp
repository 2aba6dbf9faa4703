#include "rtpro/scene/sphere_light.h"

#include "yaml_light_fields.h"

#include <string>

namespace rtpro {

void read_light_desc(const YamlNode& node, SphereLightDesc& desc) {
  const MappingReader light(node, "sphere light",
                            {"type", "name", "center", "radius", "color", "intensity", "samples"});
  desc.center = read_position(light.required("center"), light.field("center"));
  const YamlNode& radius = light.required("radius");
  desc.radius = static_cast<float>(read_number(radius, light.field("radius")));
  if (!(desc.radius > 0.0f))
    fail_at(radius, light.field("radius") + " must be positive, got " + std::string(radius.scalar()));
  read_color_and_intensity(light, desc);
  desc.samples = read_light_samples(light, desc.samples);
}

}  // namespace rtpro
