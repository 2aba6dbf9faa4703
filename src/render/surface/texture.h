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

// A sphere's texture coordinates at the unit normal `n` (in the sphere's own frame): longitude u,
// 0.5 facing +z and growing towards +x, and latitude v, 0 at the bottom and 1 at the top. Where a
// ray hits a sphere and where light sampling picks a point on one alike.
TexCoord sphere_texture_coordinates(const Vec3& n);

// An image texture at texture coordinates (u, v), v up.
Color evaluate(const ImageTexture& texture, float u, float v, const TextureLookup* images);

// The radiance `emission` has at texture coordinates (u, v): its radiance, times its image there.
Color emitted_radiance(const Emission& emission, float u, float v, const TextureLookup* images);

}  // namespace rtpro
