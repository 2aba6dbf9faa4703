#pragma once
// A material's BSDF at a shading point, and the frame it is evaluated in: each kind of surface
// model (SurfaceModel, scene/material_kinds.h) makes its BSDF in its own bsdf_from
// (render/bsdf/bsdf_from.h says what a kind declares; render/bsdf/conductor_bsdf.h and its
// neighbours, registered in render/bsdf/bsdf.h).
#include "rtpro/image/texture_lookup.h"
#include "rtpro/scene/render_scene.h"
#include "surface.h"
#include "surface_bsdf.h"

#include <concepts>
#include <cstddef>
#include <utility>
#include <variant>

namespace rtpro {

// Every function render/bsdf/bsdf_from.h asks of a kind's shading side, each by name, so that a
// kind missing one stops the build with what it lacks rather than in the visits that call it.
template <typename Surface>
constexpr bool has_shading_side() {
  static_assert(
      requires(const Surface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
        { bsdf_from(model, base_color, point, textures, out) } -> std::same_as<Vec3>;
      },
      "a material kind needs `Vec3 bsdf_from(const KindSurface&, const ColorTexture& base_color, "
      "const SurfacePoint&, const TextureLookup*, SurfaceBsdf&)` (render/bsdf/KIND_bsdf.h)");
  static_assert(
      requires(const Surface& model) {
        { makes_lambert_bsdf(model) } -> std::same_as<bool>;
      },
      "a material kind needs `bool makes_lambert_bsdf(const KindSurface&)` (render/bsdf/KIND_bsdf.h)");
  return true;
}

template <std::size_t... Kind>
constexpr bool every_kind_has_shading_side(std::index_sequence<Kind...>) {
  return (has_shading_side<std::variant_alternative_t<Kind, SurfaceModel>>() && ...);
}
static_assert(every_kind_has_shading_side(std::make_index_sequence<std::variant_size_v<SurfaceModel>>{}));

// Whether the material's BSDF is a DiffuseBsdf (lambert_surface) wherever it is hit: its kind's say.
inline bool makes_lambert_bsdf(const Material& material) {
  return std::visit([](const auto& model) { return makes_lambert_bsdf(model); }, material.model);
}
// Whether the BSDF the material makes reads bsdf_sample's u_lobe: all but a Lambert surface's,
// whose one lobe needs no choosing (a vertex's random numbers that nothing reads need not be
// drawn).
inline bool reads_lobe_choice(const Material& material) { return !makes_lambert_bsdf(material); }

// Builds the tables the scene's materials' BSDFs will look up (the rough interfaces' albedos,
// render/bsdf/dielectric_albedo.h) before the tiles start, on every thread of the task arena:
// otherwise the first tile to need one builds it alone while the others wait for it. Outside any
// render task.
void prepare_material_bsdfs(const RenderScene& scene);

// `textures`: the scene's image textures, opened, for the colour textures the material reads.
// Written into `out`, whose previous contents do not matter.
void material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures,
                   SurfaceBsdf& out);
inline SurfaceBsdf material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures) {
  SurfaceBsdf surface;
  material_bsdf(material, point, textures, surface);
  return surface;
}

}  // namespace rtpro
