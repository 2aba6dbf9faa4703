#pragma once
// A principled material (`type: principled`; every glTF material): the glTF 2.0
// metallic-roughness model and its extensions, with OpenPBR's names where one exists. The scene's
// side of the kind in one place (as scene/phong_material.h explains): its reader is
// src/scene/yaml/yaml_principled_material.cpp, the rest src/scene/build/principled_material.cpp,
// its shading side render/bsdf/principled_bsdf.h.
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

// How a subsurface radius becomes the mean free path under the surface, as Cycles' two random
// walks (render/media/subsurface_medium.h): scaled by the surface albedo, so that the radius is how
// far light diffuses ("Random Walk"), or by 1/(4π) whatever the albedo ("Random Walk (Fixed Radius)").
enum class SubsurfaceMethod { kRandomWalk, kRandomWalkFixedRadius };

// The base colour is the material's colour.
struct PrincipledParams {
  // glTF's default roughness is 1 and OpenPBR's 0.3; a principled material without one is in between.
  float roughness = 0.5f;
  float ior = 1.5f;                  // KHR_materials_ior
  float metalness = 0.0f;            // glTF metallicFactor
  float specular_weight = 1.0f;      // KHR_materials_specular specularFactor
  Color specular_color{1.0f};        // KHR_materials_specular specularColorFactor
  float transmission_weight = 0.0f;  // KHR_materials_transmission transmissionFactor
  float coat_weight = 0.0f;          // KHR_materials_clearcoat clearcoatFactor
  float coat_roughness = 0.0f;       // KHR_materials_clearcoat clearcoatRoughnessFactor
  Color fuzz_color{0.0f};            // KHR_materials_sheen sheenColorFactor
  float fuzz_roughness = 0.0f;       // KHR_materials_sheen sheenRoughnessFactor
  // Random-walk subsurface scattering (render/integrators/subsurface_walk.h), with Blender's
  // Principled BSDF's names and defaults: the share of the diffuse base that scatters under the
  // surface, how far light scatters there per channel (times the scale), and the anisotropy of
  // its phase function.
  float subsurface = 0.0f;
  Color subsurface_radius{1.0f, 0.2f, 0.1f};
  float subsurface_scale = 0.05f;
  float subsurface_anisotropy = 0.0f;
  SubsurfaceMethod subsurface_method = SubsurfaceMethod::kRandomWalk;
  // glTF metallicRoughnessTexture: roughness × its green channel, metalness × its blue one.
  std::optional<TextureSlotDesc> metallic_roughness_texture;
  // glTF normalTexture: a tangent-space normal map (+x along increasing u, +y along increasing v
  // on the image, i.e. towards its top), its x and y scaled by normal_scale.
  std::optional<TextureSlotDesc> normal_texture;
  float normal_scale = 1.0f;
};

// The model as render/bsdf/principled_bsdf.h shades it; its base colour is Material::base_color.
struct PrincipledSurface {
  float metalness, roughness, ior;
  float specular_weight;
  Color specular_color;
  float transmission_weight;
  float coat_weight, coat_roughness;
  Color fuzz_color;
  float fuzz_roughness;
  float subsurface;
  Color subsurface_radius;  // subsurface_radius × subsurface_scale
  float subsurface_anisotropy;
  SubsurfaceMethod subsurface_method;
  // roughness × green and metalness × blue of an image (its tint is (1, roughness, metalness)).
  std::optional<ImageTexture> metallic_roughness;
  std::optional<NormalMap> normal_map;
};

inline const char* material_type_name(const PrincipledParams&) { return "principled"; }
std::vector<std::string_view> material_keys(const PrincipledParams&);
void read_material_params(const MappingReader& material, PrincipledParams& params);
// Its images are registered in `textures`.
PrincipledSurface surface_model_from(const PrincipledParams& params, const MaterialDesc& material,
                                     std::vector<TextureImage>& textures);
// The Phong highlight and mirror of the metallic-roughness model (FORMAT.md, "glTF files"), and a
// diffuse colour darkened by what the mirror takes.
WhittedMaterial whitted_approximation_of(const PrincipledParams& params, const MaterialDesc& material,
                                         const ColorTexture& color);
inline bool reads_images(const PrincipledSurface& surface) { return surface.metallic_roughness || surface.normal_map; }
// It has no absorption of its own: a path through its transmission stays in the medium it was in.
inline const Dielectric* interior_of(const PrincipledSurface&) { return nullptr; }

}  // namespace rtpro
