#pragma once
// A diffuse material (`type: diffuse`): Lambert reflection of the material's colour, the scene's
// side of the kind in one place (as scene/phong_material.h explains); its reader is
// src/scene/yaml/yaml_diffuse_material.cpp, its shading side render/bsdf/diffuse_bsdf.h.
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/whitted_material.h"

#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

struct DiffuseParams {};
struct DiffuseSurface {};  // Lambert, reflectance Material::base_color

inline const char* material_type_name(const DiffuseParams&) { return "diffuse"; }
std::vector<std::string_view> material_keys(const DiffuseParams&);
void read_material_params(const MappingReader& material, DiffuseParams& params);
inline DiffuseSurface surface_model_from(const DiffuseParams&, const MaterialDesc&, std::vector<TextureImage>&) {
  return {};
}
// The material's colour, no highlight (its exponent is moot) and no mirror.
inline WhittedMaterial whitted_approximation_of(const DiffuseParams&, const MaterialDesc&, const ColorTexture& color) {
  return {color, 0.0f, 10.0f, 0.0f, std::nullopt};
}
inline bool reads_images(const DiffuseSurface&) { return false; }
inline const Dielectric* interior_of(const DiffuseSurface&) { return nullptr; }

}  // namespace rtpro
