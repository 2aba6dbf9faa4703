#pragma once
// A dielectric (`type: dielectric`: glass, water), the scene's side of the kind in one place (as
// scene/phong_material.h explains): its reader is src/scene/yaml/yaml_dielectric_material.cpp, the
// rest src/scene/build/dielectric_material.cpp, its shading side render/bsdf/dielectric_bsdf.h.
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/whitted_material.h"

#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

struct DielectricParams {
  // GGX roughness from 0 (clear glass) to 1; the distribution's alpha is roughness².
  float roughness = 0.0f;
  // White light inside it has colour `transmittance` after `transmittance_distance` scene units.
  Dielectric glass;
};

struct DielectricSurface {
  float roughness;
  Dielectric glass;  // its index, and what its inside absorbs
};

inline const char* material_type_name(const DielectricParams&) { return "dielectric"; }
std::vector<std::string_view> material_keys(const DielectricParams&);
void read_material_params(const MappingReader& material, DielectricParams& params);
DielectricSurface surface_model_from(const DielectricParams& params, const MaterialDesc&, std::vector<TextureImage>&);
// Smooth glass with a highlight as wide as its lobe.
WhittedMaterial whitted_approximation_of(const DielectricParams& params, const MaterialDesc&,
                                         const ColorTexture& color);
inline bool reads_images(const DielectricSurface&) { return false; }
inline const Dielectric* interior_of(const DielectricSurface& surface) { return &surface.glass; }

}  // namespace rtpro
