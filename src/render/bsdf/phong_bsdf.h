#pragma once
// The Phong material's shading side (its scene side is scene/phong_material.h). It has no BSDF of
// its own: under the path integrator it is a Lambert surface of its colour (render/bsdf/diffuse_bsdf.h)
// or, with glass, smooth glass (render/bsdf/dielectric_bsdf.h).
#include "rtpro/core/vec3.h"

namespace rtpro {

struct PhongSurface;  // scene/phong_material.h
struct Material;      // scene/render_scene.h
struct SurfacePoint;  // render/surface/surface.h
class TextureLookup;  // image/texture_lookup.h
struct SurfaceBsdf;   // render/bsdf/material_bsdf.h

// Its BSDF at `point`, as render/bsdf/material_bsdf.h asks of every kind: written into `out` (its frame
// left to the caller), the shading normal returned.
Vec3 bsdf_from(const PhongSurface& model, const Material& material, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);

}  // namespace rtpro
