#pragma once
// Shared after-the-hit code: turns a backend's compact hit record into a shading point.
// Both backends feed the same function, so everything downstream of the hit is identical.
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>
#include <span>

namespace rtpro {

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
};

// Writes the shading point of `hit` (a hit of `ray`) into `out`; every field is set. Filling the
// caller's record in place spares the copy of a returned one, which stalled on store forwarding.
void make_surface(const RenderScene& scene, const Ray& ray, const Hit& hit, SurfacePoint& out);

// Whether `material` reads an image (and so needs texture coordinates): its colour, its emission,
// or a principled surface's metallic-roughness or normal map. (A principled base colour image is
// its Whitted colour's too.)
inline bool has_image_texture(const RenderScene& scene, std::uint32_t material) {
  const Material& m = scene.materials[material];
  if (std::holds_alternative<ImageTexture>(m.color) || m.emission.texture) return true;
  const auto* principled = std::get_if<PrincipledSurface>(&m.model);
  return principled && (principled->metallic_roughness || principled->normal_map);
}

// Whether make_sphere_surfaces4 may take `hit`: a sphere of the top level (not instanced) whose
// material has no image texture (no texture coordinates to work out). Inline: it runs per hit.
inline bool is_plain_sphere_hit(const RenderScene& scene, const Hit& hit) {
  if (hit.inst_id != kInvalidId) return false;
  const auto* set = std::get_if<SphereSet>(&scene.top.geometries[hit.geom_id]);
  return set && !has_image_texture(scene, set->spheres[hit.prim_id].material);
}

// make_surface for four plain sphere hits at once (is_plain_sphere_hit), lane by lane in SSE2
// registers with make_surface's operations in its order: each out[i] is make_surface(scene,
// *rays[i], *hits[i]) bit for bit, and mirrors[i] is the mirror direction there,
// reflect(normalize(rays[i]->dir), out[i]->shading_normal), bit for bit. The square roots and
// divisions of a surface's normal and mirror direction are a latency chain; four lanes run one
// chain for four surfaces.
void make_sphere_surfaces4(const RenderScene& scene, const Ray* const rays[4], const Hit* const hits[4],
                           SurfacePoint* const out[4], Vec3* const mirrors[4]);

// Whether make_triangle_surfaces4 may take `hit`: a triangle of a top-level mesh (not instanced)
// whose material has no image texture.
inline bool is_plain_triangle_hit(const RenderScene& scene, const Hit& hit) {
  if (hit.inst_id != kInvalidId) return false;
  const auto* mesh = std::get_if<TriangleMesh>(&scene.top.geometries[hit.geom_id]);
  return mesh && !has_image_texture(scene, mesh->material_of(hit.prim_id));
}

// make_surface for four plain triangle hits at once (is_plain_triangle_hit), with the same
// guarantee as make_sphere_surfaces4: each out[i] is make_surface's, bit for bit, and mirrors[i]
// the mirror direction there. The hits may lie on different meshes, flat or smooth.
void make_triangle_surfaces4(const RenderScene& scene, const Ray* const rays[4], const Hit* const hits[4],
                             SurfacePoint* const out[4], Vec3* const mirrors[4]);

// make_surface for each valid hit: out[i] is make_surface(scene, rays[i], hits[i]) bit for bit, and
// the entries of misses are left as they were. Plain sphere and plain triangle hits go four at a
// time through make_sphere_surfaces4 and make_triangle_surfaces4: one latency chain of square roots
// and divisions for four surfaces.
void make_surfaces(const RenderScene& scene, std::span<const Ray> rays, std::span<const Hit> hits,
                   std::span<SurfacePoint> out);

inline SurfacePoint make_surface(const RenderScene& scene, const Ray& ray, const Hit& hit) {
  SurfacePoint sp;
  make_surface(scene, ray, hit, sp);
  return sp;
}

}  // namespace rtpro
