#pragma once
// Shared after-the-hit code: turns a backend's compact hit record into a shading point.
// Both backends feed the same function, so everything downstream of the hit is identical.
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>

namespace rtpro {

// Relative rounding error allowed for a computed surface point (position_error is this times the
// largest magnitude involved): covers the float rounding of the hit distance, the re-projection
// onto the sphere, barycentric interpolation and an instance transform, each a handful of ulps.
inline constexpr float kRelativePositionError = 0x1p-18f;

struct SurfacePoint {
  Vec3 position;
  Vec3 geometric_normal;  // unit, facing the side the ray came from
  bool front_face;        // the ray came from the outside (the side the primitive's normal points to)
  Vec3 shading_normal;    // unit, in the same hemisphere as geometric_normal
  float position_error;   // conservative bound on the rounding error of each coordinate
  std::uint32_t material;
  std::uint32_t object_id;  // top-level geometry (the instance, for instanced hits)
  // Texture coordinates (v up), worked out only when the material has an image texture: a mesh's
  // own, interpolated (its barycentrics when it has none); on a sphere longitude u (0.5 facing
  // the object's +z) and latitude v (0 at the bottom, 1 at the top, in the object's frame).
  float tex_u = 0.0f, tex_v = 0.0f;
  // Worked out with the texture coordinates, for a normal map's frame: the direction of increasing
  // u (world space, not unit; zero otherwise), and the sign that makes the outside normal × tangent
  // point along increasing v (a mirrored mapping or transform makes it −1).
  Vec3 tangent{0.0f};
  float bitangent_sign = 1.0f;
  // Where across a curve's width the ray hit, from -1 to 1: pbrt's h, the signed distance of the
  // hit from the fibre's axis over its radius, seen along the ray. A hair BSDF reads it with the
  // curve's direction in `tangent`; 0 on every other shape.
  float fiber_offset = 0.0f;
};

// Writes the shading point of `hit` (a hit of `ray`) into `out`; every field is set. Filling the
// caller's record in place spares the copy of a returned one, which stalled on store forwarding.
void make_surface(const RenderScene& scene, const Ray& ray, const Hit& hit, SurfacePoint& out);
// The surface of a hit by a ray at `time` (scene/motion.h): moving shapes and instances where
// they are then; the rest as make_surface has them.
void make_surface_at(const RenderScene& scene, const Ray& ray, float time, const Hit& hit, SurfacePoint& out);

// Whether `material` reads an image (and so needs texture coordinates): its base colour, its
// emission, its Whitted colour (the whitted integrator's albedo) or one of its model's own
// (reads_images, in the kind's header: a principled surface's metallic-roughness or normal map).
inline bool has_image_texture(const RenderScene& scene, std::uint32_t material) {
  const Material& m = scene.materials[material];
  if (std::holds_alternative<ImageTexture>(m.base_color) || std::holds_alternative<ImageTexture>(m.whitted.color) ||
      m.emission.texture)
    return true;
  return std::visit([](const auto& model) { return reads_images(model); }, m.model);
}

// A sphere's texture coordinates at the unit normal `n` (in the sphere's own frame): longitude u,
// 0.5 facing +z and growing towards +x, and latitude v, 0 at the bottom and 1 at the top. Where a
// ray hits a sphere and where light sampling picks a point on one alike.
TexCoord sphere_texture_coordinates(const Vec3& n);

inline SurfacePoint make_surface(const RenderScene& scene, const Ray& ray, const Hit& hit) {
  SurfacePoint sp;
  make_surface(scene, ray, hit, sp);
  return sp;
}

}  // namespace rtpro
