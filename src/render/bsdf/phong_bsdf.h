#pragma once
// The Phong material's shading side (its scene side is scene/phong_material.h). It has no BSDF of
// its own: under the path integrator it is a Lambert surface of its colour (render/bsdf/diffuse_bsdf.h)
// or, with glass, smooth glass (render/bsdf/dielectric_bsdf.h).
#include "bsdf_from.h"

namespace rtpro {

struct PhongSurface;  // scene/phong_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const PhongSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
// Without glass it is a Lambert surface.
bool makes_lambert_bsdf(const PhongSurface& model);

}  // namespace rtpro
