#include "rtpro/scene/dielectric_material.h"

#include "yaml_material_fields.h"

namespace rtpro {

std::vector<std::string_view> material_keys(const DielectricParams&) {
  return {"roughness", "ior", "transmittance", "transmittance_distance"};
}

void read_material_params(const MappingReader& material, DielectricParams& params) {
  read_roughness(material, params.roughness);
  read_ior(material, params.glass.ior);
  read_absorption(material, params.glass);
}

}  // namespace rtpro
