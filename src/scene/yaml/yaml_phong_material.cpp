#include "rtpro/scene/phong_material.h"

#include "yaml_material_fields.h"

#include <string>

namespace rtpro {

std::vector<std::string_view> material_keys(const PhongParams&) {
  return {"specular", "shininess", "reflectivity", "ior", "transmittance", "transmittance_distance"};
}

void read_material_params(const MappingReader& material, PhongParams& params) {
  if (const YamlNode* specular = material.optional("specular"))
    params.specular = read_non_negative(*specular, material.field("specular"));
  if (const YamlNode* shininess = material.optional("shininess"))
    params.shininess = read_non_negative(*shininess, material.field("shininess"));
  read_unit(material, "reflectivity", params.reflectivity);
  // Glass: an index of refraction, and then what it absorbs.
  if (material.optional("ior")) read_ior(material, params.glass.emplace().ior);
  const YamlNode* transmittance = material.optional("transmittance");
  const YamlNode* distance = material.optional("transmittance_distance");
  if ((transmittance || distance) && !params.glass)
    fail_at(transmittance ? *transmittance : *distance,
            material.field(transmittance ? "transmittance" : "transmittance_distance") +
                " describes absorption inside glass: give the material an ior too");
  if (params.glass) read_absorption(material, *params.glass);
}

}  // namespace rtpro
