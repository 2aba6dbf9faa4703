#pragma once
// Evaluating a material's colour texture at a shading point.
#include "rtpro/core/vec3.h"
#include "rtpro/image/texture_lookup.h"
#include "surface.h"
#include "rtpro/scene/render_scene.h"

namespace rtpro {

// The colour of `texture` at the shading point: procedural ones from its world position, image
// ones from its texture coordinates through `images` (the scene's textures, opened; needed only
// when the scene has image textures).
Color evaluate(const ColorTexture& texture, const SurfacePoint& point, const TextureLookup* images);

// An image texture at texture coordinates (u, v), v up.
Color evaluate(const ImageTexture& texture, float u, float v, const TextureLookup* images);

// The radiance `emission` has at texture coordinates (u, v): its radiance, times its image there.
Color emitted_radiance(const Emission& emission, float u, float v, const TextureLookup* images);

}  // namespace rtpro
