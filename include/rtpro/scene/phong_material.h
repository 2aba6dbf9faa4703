#pragma once
// The Phong material (`type: phong`, a material without a type), the scene's side of a material
// kind in one place: its parameters, its keys in a scene file (read in
// src/scene/yaml/yaml_phong_material.cpp), the surface model the path integrator shades and what
// the whitted integrator shades. Its shading side is render/bsdf/phong_bsdf.h; the kind is registered in
// scene/material_kinds.h.
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/whitted_material.h"

#include <optional>
#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

// The Whitted model: the material's colour, a highlight, a mirror reflection.
struct PhongParams {
  float specular = 0.5f;      // Phong highlight weight
  float shininess = 10.0f;    // Phong exponent
  float reflectivity = 0.0f;  // weight of the mirror reflection
  // An index of refraction makes the material a smooth dielectric (Fresnel-weighted reflection and
  // refraction, highlights from `specular`, no diffuse part).
  std::optional<Dielectric> glass;
};

// Under the path integrator (render/bsdf/phong_bsdf.h): the Whitted model's diffuse colour,
// highlight and mirror as an energy-conserving mix of Lambert, GGX and mirror reflection or, with
// glass, smooth glass. Without highlight and mirror (the defaults here) it is a Lambert surface.
struct PhongSurface {
  float specular = 0.0f;
  float shininess = 10.0f;
  float reflectivity = 0.0f;
  std::optional<Dielectric> glass;
};

inline const char* material_type_name(const PhongParams&) { return "phong"; }
// The keys it reads besides type, colour and emission.
std::vector<std::string_view> material_keys(const PhongParams&);
void read_material_params(const MappingReader& material, PhongParams& params);
inline PhongSurface surface_model_from(const PhongParams& params, const MaterialDesc&, std::vector<TextureImage>&) {
  return {params.specular, params.shininess, params.reflectivity, params.glass};
}
// It is the Whitted model: `color` is the material's colour.
inline WhittedMaterial whitted_approximation_of(const PhongParams& params, const MaterialDesc&,
                                                const ColorTexture& color) {
  return {color, params.specular, params.shininess, params.reflectivity, params.glass};
}
inline bool reads_images(const PhongSurface&) { return false; }
inline const Dielectric* interior_of(const PhongSurface& surface) { return surface.glass ? &*surface.glass : nullptr; }

}  // namespace rtpro
