#pragma once
// A conductor (`type: conductor`, a metal), the scene's side of the kind in one place (as
// scene/phong_material.h explains): its reader is src/scene/yaml/yaml_conductor_material.cpp, the
// rest src/scene/build/conductor_material.cpp, its shading side render/bsdf/conductor_bsdf.h.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/whitted_material.h"

#include <optional>
#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

struct ConductorParams {
  // GGX roughness from 0 (smooth, a perfect mirror) to 1; the distribution's alpha is roughness².
  float roughness = 0.0f;
  // A complex index of refraction eta + i·k per channel (measured metals); unset, the conductor's
  // reflectance at normal incidence is the material's colour (Schlick's Fresnel).
  std::optional<Color> eta, k;
};

struct ConductorSurface {
  float roughness;
  // A complex index eta + i·k per channel; without one, Material::base_color is the reflectance
  // at normal incidence.
  bool has_complex_ior;
  Color eta, k;
};

inline const char* material_type_name(const ConductorParams&) { return "conductor"; }
std::vector<std::string_view> material_keys(const ConductorParams&);
void read_material_params(const MappingReader& material, ConductorParams& params);
ConductorSurface surface_model_from(const ConductorParams& params, const MaterialDesc&, std::vector<TextureImage>&);
// The material's colour, a highlight as wide as its lobe, and a mirror while it is nearly smooth.
WhittedMaterial whitted_approximation_of(const ConductorParams& params, const MaterialDesc&, const ColorTexture& color);
inline bool reads_images(const ConductorSurface&) { return false; }
inline const Dielectric* interior_of(const ConductorSurface&) { return nullptr; }

}  // namespace rtpro
