#include "rtpro/scene/hair_material.h"

#include "yaml_material_fields.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

namespace rtpro {

namespace {

// β_m and β_n: above 0 (a perfectly smooth fibre is a delta the model cannot sample) up to 1.
void read_fibre_roughness(const MappingReader& material, const char* key, float& beta) {
  const YamlNode* node = material.optional(key);
  if (!node) return;
  const double value = read_number(*node, material.field(key));
  if (!(value > 0.0) || value > 1.0)
    fail_at(*node, material.field(key) + " is a roughness above 0 and at most 1 (0.3 for human hair), got " +
                       std::string(node->scalar()));
  beta = std::max(static_cast<float>(value), 1e-3f);
}

void read_tilt(const MappingReader& material, float& degrees) {
  const YamlNode* node = material.optional("alpha");
  if (!node) return;
  const double value = read_number(*node, material.field("alpha"));
  if (!(std::fabs(value) <= 90.0))
    fail_at(*node, material.field("alpha") + " is the cuticle scales' tilt in degrees, from -90 to 90 (about 2 for " +
                       "human hair), got " + std::string(node->scalar()));
  degrees = static_cast<float>(value);
}

// The absorption: sigma_a, melanin (with pheomelanin) or the colour, exactly one. A material read
// over a model's (which may have one already) need not repeat it.
void read_absorption_source(const MappingReader& material, HairParams& params) {
  const std::array<std::pair<const char*, HairAbsorption>, 3> sources{
      {{"sigma_a", HairAbsorption::kSigmaA}, {"melanin", HairAbsorption::kMelanin}, {"color", HairAbsorption::kColor}}};
  const char* given = nullptr;
  HairAbsorption source = HairAbsorption::kUnset;
  for (const auto& [key, kind] : sources) {
    const YamlNode* node = material.optional(key);
    if (!node) continue;
    if (given)
      fail_at(*node, material.field(key) + ": hair takes its absorption from one of sigma_a, melanin or color, and " +
                         given + " is given already");
    given = key;
    source = kind;
  }
  const YamlNode* pheomelanin = material.optional("pheomelanin");
  if (pheomelanin && source != HairAbsorption::kMelanin)
    fail_at(*pheomelanin, material.field("pheomelanin") +
                              " is the red pigment beside melanin (eumelanin): give melanin too, 0 for none");
  if (source == HairAbsorption::kUnset && params.absorption == HairAbsorption::kUnset)
    fail_at(material.optional("type") ? *material.optional("type") : material.node(),
            material.field("type") +
                ": hair needs its absorption: sigma_a: [r, g, b], melanin: m (0.3 blonde, 1.3 "
                "brown, 8 black) or color: [r, g, b]");
  if (source == HairAbsorption::kSigmaA) {
    const YamlNode& node = material.required("sigma_a");
    const Vec3 sigma_a = read_vec3(node, material.field("sigma_a"));
    if (std::min({sigma_a.x, sigma_a.y, sigma_a.z}) < 0.0f)
      fail_at(node,
              material.field("sigma_a") + " is an absorption coefficient per fibre radius: each channel 0 or more");
    params.sigma_a = sigma_a;
  } else if (source == HairAbsorption::kMelanin) {
    params.eumelanin = read_non_negative(material.required("melanin"), material.field("melanin"));
    params.pheomelanin = pheomelanin ? read_non_negative(*pheomelanin, material.field("pheomelanin")) : 0.0f;
  }
  if (source != HairAbsorption::kUnset) params.absorption = source;
}

}  // namespace

std::vector<std::string_view> material_keys(const HairParams&) {
  return {"beta_m", "beta_n", "alpha", "ior", "sigma_a", "melanin", "pheomelanin"};
}

void read_material_params(const MappingReader& material, HairParams& params) {
  read_fibre_roughness(material, "beta_m", params.beta_m);
  read_fibre_roughness(material, "beta_n", params.beta_n);
  read_tilt(material, params.alpha_degrees);
  if (const YamlNode* ior = material.optional("ior")) {
    read_ior(material, params.ior);
    if (params.ior < 1.0f)
      fail_at(*ior, material.field("ior") + " is the fibre's index of refraction: 1 or more (1.55 for keratin), got " +
                        std::string(ior->scalar()));
  }
  read_absorption_source(material, params);
}

}  // namespace rtpro
