#include "rtpro/scene/conductor_material.h"

#include "yaml_material_fields.h"

#include <algorithm>

namespace rtpro {

std::vector<std::string_view> material_keys(const ConductorParams&) { return {"roughness", "eta", "k"}; }

// roughness 0..1 and a complex index (eta and k together).
void read_material_params(const MappingReader& material, ConductorParams& params) {
  read_roughness(material, params.roughness);
  const YamlNode* eta = material.optional("eta");
  const YamlNode* k = material.optional("k");
  if (!eta != !k)
    fail_at(eta ? *eta : *k,
            material.field(eta ? "eta" : "k") +
                ": a complex index of refraction needs both eta and k (gold: eta [0.143, 0.374, 1.442], "
                "k [3.983, 2.385, 1.603])");
  if (!eta) return;
  params.eta = read_color(*eta, material.field("eta"));
  params.k = read_color(*k, material.field("k"));
  if (std::min({params.eta->x, params.eta->y, params.eta->z}) <= 0.0f)
    fail_at(*eta, material.field("eta") + " must be above 0 in each channel");
  if (std::min({params.k->x, params.k->y, params.k->z}) < 0.0f)
    fail_at(*k, material.field("k") + " must be 0 or more in each channel");
}

}  // namespace rtpro
