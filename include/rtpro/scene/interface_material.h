#pragma once
// An interface (`type: interface`): no surface at all, only the boundary of the medium inside it
// (its `interior:`, vacuum without one). Rays cross it unbent and unweighted, as an index-matched
// boundary (pbrt's `interface` material, a Cycles object with a volume shader and no surface).
// The scene's side of the kind in one place (as scene/phong_material.h explains); its reader is
// src/scene/yaml/yaml_interface_material.cpp, its shading side render/bsdf/interface_bsdf.h.
#include "rtpro/scene/dielectric.h"
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/whitted_material.h"

#include <string_view>
#include <vector>

namespace rtpro {

struct MaterialDesc;  // scene/description.h
class MappingReader;  // src/scene/yaml/yaml_reader.h

struct InterfaceParams {};
struct InterfaceSurface {};

inline const char* material_type_name(const InterfaceParams&) { return "interface"; }
std::vector<std::string_view> material_keys(const InterfaceParams&);
void read_material_params(const MappingReader& material, InterfaceParams& params);
inline InterfaceSurface surface_model_from(const InterfaceParams&, const MaterialDesc&, std::vector<TextureImage>&) {
  return {};
}
// Glass of index 1 without a highlight: the Whitted integrator's rays pass straight through it.
inline WhittedMaterial whitted_approximation_of(const InterfaceParams&, const MaterialDesc&,
                                                const ColorTexture& color) {
  return {color, 0.0f, 10.0f, 0.0f, Dielectric{1.0f}};
}
inline bool reads_images(const InterfaceSurface&) { return false; }
inline const Dielectric* interior_of(const InterfaceSurface&) { return nullptr; }

}  // namespace rtpro
