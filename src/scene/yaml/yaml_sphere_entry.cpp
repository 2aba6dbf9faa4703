#include "rtpro/scene/sphere_geometry.h"

#include "yaml_light_linking.h"
#include "yaml_shape_entry.h"

#include <string>

namespace rtpro {

void read_shape_entry(const YamlNode& node, ShapeEntryReader& reader, std::vector<SphereDesc>& spheres) {
  const MappingReader sphere(node, "sphere",
                             {"type", "center", "radius", "material", "interior", kLightLinkingKey, kShadowLinkingKey});
  SphereDesc desc;
  if (const YamlNode* center = sphere.optional("center")) {
    const auto read_center = [&](const YamlNode& at) { return read_position(at, sphere.field("center")); };
    desc.center = read_center(*center);
    desc.center_steps = reader.motion().position_steps(*center, read_center);
  }
  if (const YamlNode* radius = sphere.optional("radius")) {
    const double value = read_number(*radius, sphere.field("radius"));
    if (!(value > 0.0)) fail_at(*radius, sphere.field("radius") + " must be > 0, got " + std::string(radius->scalar()));
    desc.radius = static_cast<float>(value);
  }
  if (const YamlNode* material = sphere.optional("material"))
    desc.material = reader.material_index(*material, sphere.field("material"));
  desc.material = reader.with_interior(sphere, desc.material);
  desc.linking = reader.read_linking(sphere);
  spheres.push_back(desc);
}

}  // namespace rtpro
