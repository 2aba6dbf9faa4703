#pragma once
// make_surface for many hits at once: plain sphere and triangle hits (top-level, no image texture)
// four at a time in SSE2 lanes (AVX2 encodings where the CPU has them), each surface make_surface's
// bit for bit, and a batch of hits with the plain ones grouped into fours.
#include "surface.h"

#include <span>

namespace rtpro {

// Whether make_sphere_surfaces4 may take `hit`: a sphere of the top level (not instanced) whose
// material has no image texture (no texture coordinates to work out). Inline: it runs per hit.
inline bool is_plain_sphere_hit(const RenderScene& scene, const Hit& hit) {
  if (hit.inst_id != kInvalidId) return false;
  const auto* set = std::get_if<SphereSet>(&scene.top.geometries[hit.geom_id]);
  return set && !set->moving() && !has_image_texture(scene, set->spheres[hit.prim_id].material);
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
  return mesh && !mesh->moving() && !has_image_texture(scene, mesh->material_of(hit.prim_id));
}

// make_surface for four plain triangle hits at once (is_plain_triangle_hit), with the same
// guarantee as make_sphere_surfaces4: each out[i] is make_surface's, bit for bit, and mirrors[i]
// the mirror direction there. The hits may lie on different meshes, flat or smooth.
void make_triangle_surfaces4(const RenderScene& scene, const Ray* const rays[4], const Hit* const hits[4],
                             SurfacePoint* const out[4], Vec3* const mirrors[4]);

// make_surface for each valid hit: out[i] is make_surface(scene, rays[i], hits[i]) bit for bit, and
// the entries of misses are left as they were. Plain sphere and plain triangle hits go four at a
// time through make_sphere_surfaces4 and make_triangle_surfaces4: one latency chain of square roots
// and divisions for four surfaces. `prefetch`: hit_prefetch_pays(scene) (hit_prefetch.h).
void make_surfaces(const RenderScene& scene, bool prefetch, std::span<const Ray> rays, std::span<const Hit> hits,
                   std::span<SurfacePoint> out);
// The same for rays at `times` (scene/motion.h; empty: the call above), one by one with
// make_surface_at.
void make_surfaces(const RenderScene& scene, bool prefetch, std::span<const Ray> rays, std::span<const float> times,
                   std::span<const Hit> hits, std::span<SurfacePoint> out);

}  // namespace rtpro
