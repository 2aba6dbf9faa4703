#include "yaml_material_fields.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rtpro {

void read_roughness(const MappingReader& material, float& roughness) {
  const YamlNode* node = material.optional("roughness");
  if (!node) return;
  roughness = read_non_negative(*node, material.field("roughness"));
  if (roughness > 1.0f)
    fail_at(*node, material.field("roughness") + " must be from 0 (smooth) to 1, got " + std::string(node->scalar()));
}

void read_ior(const MappingReader& material, float& ior) {
  const YamlNode* node = material.optional("ior");
  if (!node) return;
  const double index = read_number(*node, material.field("ior"));
  if (!(index > 0.0) || !(index <= 100.0))
    fail_at(*node, material.field("ior") + " is an index of refraction: above 0 (glass 1.5, water 1.33), got " +
                       std::string(node->scalar()));
  ior = static_cast<float>(index);
}

void read_absorption(const MappingReader& material, Dielectric& glass) {
  if (const YamlNode* transmittance = material.optional("transmittance")) {
    glass.transmittance = read_color(*transmittance, material.field("transmittance"));
    if (std::max({glass.transmittance.x, glass.transmittance.y, glass.transmittance.z}) > 1.0f)
      fail_at(*transmittance, material.field("transmittance") + " is a fraction of light kept: each channel 0 to 1");
  }
  if (const YamlNode* distance = material.optional("transmittance_distance")) {
    const double d = read_number(*distance, material.field("transmittance_distance"));
    if (!(d > 0.0) || !std::isfinite(static_cast<float>(d)))
      fail_at(*distance, material.field("transmittance_distance") + " must be a positive distance, got " +
                             std::string(distance->scalar()));
    glass.transmittance_distance = static_cast<float>(d);
  }
}

void read_unit(const MappingReader& material, const char* key, float& value) {
  const YamlNode* node = material.optional(key);
  if (!node) return;
  value = read_non_negative(*node, material.field(key));
  if (value > 1.0f) fail_at(*node, material.field(key) + " must be from 0 to 1, got " + std::string(node->scalar()));
}

void read_unit_color(const MappingReader& material, const char* key, Color& value) {
  const YamlNode* node = material.optional(key);
  if (!node) return;
  value = read_color(*node, material.field(key));
  if (max_component(value) > 1.0f) fail_at(*node, material.field(key) + " must be from 0 to 1 in each channel");
}

}  // namespace rtpro
