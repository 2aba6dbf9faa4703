#include "yaml_medium.h"

#include "yaml_reader.h"

#include <cmath>
#include <string>

namespace rtpro {

namespace {

// Coefficients per scene unit: each channel 0 or more (no 8-bit colour rule: 2 is a density).
Color read_coefficients(const YamlNode& node, const std::string& name) {
  const Vec3 value = read_vec3(node, name);
  if (std::min({value.x, value.y, value.z}) < 0.0f)
    fail_at(node, name + " is a coefficient per scene unit: each channel 0 or more");
  return value;
}

}  // namespace

Medium read_medium(const YamlNode& node, const std::string& name) {
  const MappingReader medium(node, name, {"type", "sigma_a", "sigma_s", "color", "density", "anisotropy", "emission"});
  if (const YamlNode* type = medium.optional("type"))
    read_keyword<int>(*type, medium.field("type"), {{"homogeneous", 0}});
  HomogeneousMedium homogeneous;
  const YamlNode* sigma_a = medium.optional("sigma_a");
  const YamlNode* sigma_s = medium.optional("sigma_s");
  const YamlNode* color = medium.optional("color");
  const YamlNode* density = medium.optional("density");
  if ((sigma_a || sigma_s) && (color || density))
    fail_at(color ? *color : *density, medium.field(color ? "color" : "density") +
                                           ": give either sigma_a and sigma_s, or color (the albedo) and density");
  if (sigma_a) homogeneous.sigma_a = read_coefficients(*sigma_a, medium.field("sigma_a"));
  if (sigma_s) homogeneous.sigma_s = read_coefficients(*sigma_s, medium.field("sigma_s"));
  if (color || density) {
    // Cycles' Principled Volume reading: σs = albedo × density, σa = (1 − albedo) × density.
    Color albedo(1.0f);
    float extinction = 1.0f;
    if (color) {
      albedo = read_color(*color, medium.field("color"));
      if (max_component(albedo) > 1.0f)
        fail_at(*color, medium.field("color") + " is the albedo σs/σt: each channel from 0 to 1");
    }
    if (density) extinction = read_non_negative(*density, medium.field("density"));
    homogeneous.sigma_s = albedo * extinction;
    homogeneous.sigma_a = (Color(1.0f) - albedo) * extinction;
  }
  if (const YamlNode* g = medium.optional("anisotropy")) {
    const double value = read_number(*g, medium.field("anisotropy"));
    if (!(std::fabs(value) < 1.0))
      fail_at(*g, medium.field("anisotropy") +
                      " is Henyey-Greenstein's g: strictly between -1 (back) and 1 (forward), got " +
                      std::string(g->scalar()));
    homogeneous.anisotropy = static_cast<float>(value);
  }
  if (const YamlNode* emission = medium.optional("emission"))
    homogeneous.emission = read_coefficients(*emission, medium.field("emission"));
  return homogeneous;
}

}  // namespace rtpro
