#pragma once
// A diffuse material (`type: diffuse`): Lambert reflection of the material's colour, the scene's
// side of the kind in one place (as scene/phong_material.h explains); its reader is
// src/scene/yaml/yaml_diffuse_material.cpp, its shading side render/diffuse_bsdf.h.
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/whitted_fields.h"

#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

struct DiffuseParams {};
struct DiffuseSurface {};  // Lambert, reflectance Material::color

inline const char* material_type_name(const DiffuseParams&) { return "diffuse"; }
std::vector<std::string_view> material_keys(const DiffuseParams&);
void read_material_params(const MappingReader& material, DiffuseParams& params);
inline DiffuseSurface surface_model_from(const DiffuseParams&, const MaterialDesc&, std::vector<TextureImage>&) {
  return {};
}
// No highlight (its exponent is moot) and no mirror.
inline WhittedFields whitted_approximation_of(const DiffuseParams&, const MaterialDesc&) {
  return {0.0f, 10.0f, 0.0f, std::nullopt};
}
inline bool reads_images(const DiffuseSurface&) { return false; }

}  // namespace rtpro
