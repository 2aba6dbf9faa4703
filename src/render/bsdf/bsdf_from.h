#pragma once
// What a material kind's shading side (render/bsdf/KIND_bsdf.h) declares beside its BSDF, found
// by overload on its surface model (scene/KIND_material.h) and asked for by name in
// render/bsdf/material_bsdf.h:
//
//   // Its BSDF at `point`, written into `out` (its frame left to the caller), the shading normal
//   // returned. `base_color` is Material::base_color, the colour every kind has.
//   Vec3 bsdf_from(const KindSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
//                  const TextureLookup* textures, SurfaceBsdf& out);
//   // Whether that BSDF is a DiffuseBsdf (lambert_surface, render/bsdf/surface_bsdf.h) wherever
//   // the material is hit.
//   bool makes_lambert_bsdf(const KindSurface& model);
//
// The kind's source includes render/bsdf/surface_bsdf.h, where the BSDF it writes is defined.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/material_textures.h"

namespace rtpro {

struct SurfacePoint;  // render/surface/surface.h
class TextureLookup;  // image/texture_lookup.h
struct SurfaceBsdf;   // render/bsdf/surface_bsdf.h

}  // namespace rtpro
