#pragma once
// The kinds of material, registered: each kind's scene side is one header (its parameters, its
// `type:` and keys, its surface model, its Whitted approximation and its interior: see
// scene/phong_material.h) and its shading side another (render/bsdf/phong_bsdf.h, registered in
// render/bsdf/bsdf.h). A new kind is a header here, an alternative in each variant below and its
// include; the static_assert below then names each function its header still lacks.
#include "rtpro/scene/conductor_material.h"
#include "rtpro/scene/dielectric_material.h"
#include "rtpro/scene/diffuse_material.h"
#include "rtpro/scene/hair_material.h"
#include "rtpro/scene/interface_material.h"
#include "rtpro/scene/phong_material.h"
#include "rtpro/scene/principled_material.h"

#include <concepts>
#include <cstddef>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace rtpro {

// What the scene file says of a material besides what every kind has (MaterialDesc), in the order
// its messages list the kinds.
using MaterialParams = std::variant<PhongParams, DiffuseParams, ConductorParams, DielectricParams, PrincipledParams,
                                    HairParams, InterfaceParams>;

// What the path integrator evaluates at a surface (render/bsdf/material_bsdf.h makes its BSDF), in
// MaterialParams' order.
using SurfaceModel = std::variant<PhongSurface, DiffuseSurface, ConductorSurface, DielectricSurface, PrincipledSurface,
                                  HairSurface, InterfaceSurface>;

// Every function the generic code calls on a kind's scene side, each asked for by name, so that a
// kind missing one stops the build with what it lacks rather than in the visits that call it.
template <typename Params, typename Surface>
constexpr bool has_scene_side() {
  static_assert(
      requires(const Params& p) {
        { material_type_name(p) } -> std::convertible_to<const char*>;
      },
      "a material kind needs `const char* material_type_name(const KindParams&)` (scene/KIND_material.h)");
  static_assert(
      requires(const Params& p) {
        { material_keys(p) } -> std::same_as<std::vector<std::string_view>>;
      },
      "a material kind needs `std::vector<std::string_view> material_keys(const KindParams&)` (scene/KIND_material.h)");
  static_assert(
      requires(const MappingReader& reader, Params& p) { read_material_params(reader, p); },
      "a material kind needs `void read_material_params(const MappingReader&, KindParams&)` "
      "(scene/KIND_material.h, defined in src/scene/yaml/yaml_KIND_material.cpp)");
  static_assert(
      requires(const Params& p, const MaterialDesc& desc, std::vector<TextureImage>& textures) {
        { surface_model_from(p, desc, textures) } -> std::same_as<Surface>;
      },
      "a material kind needs `KindSurface surface_model_from(const KindParams&, const MaterialDesc&, "
      "std::vector<TextureImage>&)` (scene/KIND_material.h), its surface model in SurfaceModel at its "
      "parameters' place in MaterialParams");
  static_assert(
      requires(const Params& p, const MaterialDesc& desc, const ColorTexture& color) {
        { whitted_approximation_of(p, desc, color) } -> std::same_as<WhittedMaterial>;
      },
      "a material kind needs `WhittedMaterial whitted_approximation_of(const KindParams&, const MaterialDesc&, "
      "const ColorTexture& color)` (scene/KIND_material.h)");
  static_assert(
      requires(const Surface& s) {
        { reads_images(s) } -> std::same_as<bool>;
      },
      "a material kind needs `bool reads_images(const KindSurface&)` (scene/KIND_material.h)");
  static_assert(
      requires(const Surface& s) {
        { interior_of(s) } -> std::same_as<const Dielectric*>;
      },
      "a material kind needs `const Dielectric* interior_of(const KindSurface&)` (scene/KIND_material.h): "
      "the medium inside it, nullptr for none");
  return true;
}

template <std::size_t... Kind>
constexpr bool every_kind_has_scene_side(std::index_sequence<Kind...>) {
  return (has_scene_side<std::variant_alternative_t<Kind, MaterialParams>,
                         std::variant_alternative_t<Kind, SurfaceModel>>() &&
          ...);
}

static_assert(std::variant_size_v<SurfaceModel> == std::variant_size_v<MaterialParams>,
              "a material kind needs its alternative in both MaterialParams and SurfaceModel, at the same place");
static_assert(every_kind_has_scene_side(std::make_index_sequence<std::variant_size_v<MaterialParams>>{}));

}  // namespace rtpro
