#pragma once
// Hair (`type: hair`): Chiang et al.'s fibre model (render/bsdf/hair_bsdf.h, pbrt-v4's HairBxDF),
// the scene's side of the kind in one place (as scene/phong_material.h explains): its reader is
// src/scene/yaml/yaml_hair_material.cpp, the rest src/scene/build/hair_material.cpp. The fibre runs
// along the surface's tangent: a curve's direction, on other shapes the direction of increasing
// texture u (scenes/FORMAT.md, "Hair").
#include "rtpro/core/vec3.h"
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/whitted_material.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

// What the scene file gave for the absorption: exactly one of the three.
enum class HairAbsorption : std::uint8_t { kUnset, kSigmaA, kMelanin, kColor };

// pbrt-v4's defaults.
struct HairParams {
  float beta_m = 0.3f;         // longitudinal roughness, (0, 1]
  float beta_n = 0.3f;         // azimuthal roughness, (0, 1]
  float alpha_degrees = 2.0f;  // the cuticle scales' tilt
  float ior = 1.55f;           // keratin
  HairAbsorption absorption = HairAbsorption::kUnset;
  Color sigma_a{0.0f};                         // per unit of the fibre's radius (kSigmaA)
  float eumelanin = 0.0f, pheomelanin = 0.0f;  // kMelanin
  // kColor: the material's colour (Material::base_color, which may be a texture) is the colour
  // the hair shows, σa worked out from it at each hit.
};

struct HairSurface {
  float beta_m, beta_n, alpha_degrees, ior;
  bool sigma_a_from_color;  // σa from Material::base_color at the hit; else the two below
  Color sigma_a;
  Color color;  // the colour that σa gives (the albedo AOV's)
};

inline const char* material_type_name(const HairParams&) { return "hair"; }
std::vector<std::string_view> material_keys(const HairParams&);
void read_material_params(const MappingReader& material, HairParams& params);
HairSurface surface_model_from(const HairParams& params, const MaterialDesc&, std::vector<TextureImage>&);
// The hair's colour, diffuse, with a highlight as wide as β_m and as strong as the cuticle's
// Fresnel reflection at normal incidence; no mirror.
WhittedMaterial whitted_approximation_of(const HairParams& params, const MaterialDesc&, const ColorTexture& color);
// Its fibre runs along SurfacePoint::tangent, which is worked out with the texture coordinates.
inline bool reads_images(const HairSurface&) { return true; }
inline const Dielectric* interior_of(const HairSurface&) { return nullptr; }

}  // namespace rtpro
