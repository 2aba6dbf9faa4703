#include "rtpro/scene/quad_light.h"

#include "yaml_light_fields.h"

namespace rtpro {

void read_light_desc(const YamlNode& node, QuadLightDesc& desc) {
  const MappingReader light(node, "quad light",
                            {"type", "name", "position", "edge1", "edge2", "color", "intensity", "samples"});
  desc.position = read_position(light.required("position"), light.field("position"));
  const YamlNode& edge1 = light.required("edge1");
  const YamlNode& edge2 = light.required("edge2");
  desc.edge1 = read_vec3(edge1, light.field("edge1"));
  desc.edge2 = read_vec3(edge2, light.field("edge2"));
  const Vec3 n = cross(desc.edge1, desc.edge2);
  if (!(length(n) > 1e-12f * length(desc.edge1) * length(desc.edge2)) || !(length(n) > 0.0f))
    fail_at(edge2, light.field("edge2") + " must not be zero or parallel to edge1: the quad has no area");
  read_color_and_intensity(light, desc);
  desc.samples = read_light_samples(light, desc.samples);
}

}  // namespace rtpro
