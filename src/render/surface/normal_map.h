#pragma once
// The normal a tangent-space normal map (scene/material_textures.h, NormalMap) gives at a shading
// point.
#include "rtpro/core/vec3.h"
#include "rtpro/image/texture_lookup.h"
#include "surface.h"
#include "rtpro/scene/material_textures.h"

namespace rtpro {

// On the side the ray came from; the shading normal where the map or the surface's frame says
// nothing usable (a degenerate tangent, a mapped normal facing away from the ray).
Vec3 mapped_normal(const NormalMap& map, const SurfacePoint& point, const TextureLookup* textures);

}  // namespace rtpro
