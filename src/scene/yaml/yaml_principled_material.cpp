#include "rtpro/scene/principled_material.h"

#include "yaml_material_fields.h"

namespace rtpro {

std::vector<std::string_view> material_keys(const PrincipledParams&) {
  return {"roughness",           "ior",         "metalness",      "specular_weight", "specular_color",
          "transmission_weight", "coat_weight", "coat_roughness", "fuzz_color",      "fuzz_roughness"};
}

// Its weights and colours, each from 0 to 1.
void read_material_params(const MappingReader& material, PrincipledParams& params) {
  read_roughness(material, params.roughness);
  read_unit(material, "metalness", params.metalness);
  read_unit(material, "specular_weight", params.specular_weight);
  read_unit_color(material, "specular_color", params.specular_color);
  read_unit(material, "transmission_weight", params.transmission_weight);
  read_unit(material, "coat_weight", params.coat_weight);
  read_unit(material, "coat_roughness", params.coat_roughness);
  read_unit_color(material, "fuzz_color", params.fuzz_color);
  read_unit(material, "fuzz_roughness", params.fuzz_roughness);
  read_ior(material, params.ior);
}

}  // namespace rtpro
