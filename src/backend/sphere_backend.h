#pragma once
// Spheres in the backends, the kind's backend side in one place (its scene side is
// scene/sphere_geometry.h): the native traversal's hits, single rays and packets, through
// geometry/sphere_intersect.h; the same packet test answers Embree as a user geometry
// (embree_user_geometry.h), so top-level sphere hits are bit-identical between the backends; and
// what the Embree scene builder needs. Registered in backend_shapes.h.
#include "embree_handles.h"
#include "ray_packet.h"
#include "shape_hit.h"
#include "sphere_lanes.h"
#include "rtpro/core/ray.h"
#include "rtpro/geometry/sphere_intersect.h"
#include "rtpro/scene/render_scene.h"

#include <embree3/rtcore.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <string>

namespace rtpro {

// Sphere `prim` against one ray, within (ray.tnear, t_max).
[[gnu::always_inline]] inline bool native_hit(const SphereSet& set, std::uint32_t prim, const Ray& ray, float t_max,
                                              ShapeHit& hit) {
  const Sphere& s = set.spheres[prim];
  hit.u = hit.v = 0.0f;
  return intersect_sphere(s.center, s.radius, ray.org, ray.dir, ray.tnear, t_max, hit.t);
}

// Sphere `prim` of a moving set against one ray at `time`, within (ray.tnear, t_max): the native
// traversal and Embree's callbacks both answer moving spheres with it, so their hits agree bit for bit.
[[gnu::always_inline]] inline bool native_hit_at(const SphereSet& set, std::uint32_t prim, const Ray& ray, float time,
                                                 float t_max, ShapeHit& hit) {
  hit.u = hit.v = 0.0f;
  return intersect_sphere(set.center_at(prim, time), set.spheres[prim].radius, ray.org, ray.dir, ray.tnear, t_max,
                          hit.t);
}

// Sphere `prim` against the `active` lanes of `rays` (a native packet's or Embree's), each within
// its own closed [tnear, tfar]: on_hit(k, t, u, v) for every lane k that meets it, in lane order.
// The lanes are tested together. Embree's user-geometry callbacks (embree_user_geometry.h) call it
// as the native packets do.
template <typename OnHit>
[[gnu::always_inline]] inline void hit_lanes(const SphereSet& set, std::uint32_t prim, const RayLanes& rays,
                                             std::uint32_t active, OnHit&& on_hit) {
  const Sphere& s = set.spheres[prim];
  float t[32];  // RayLanes::count is at most 32
  for (std::uint32_t hit = intersect_sphere_lanes(s.center, s.radius, rays, active, t); hit != 0; hit &= hit - 1) {
    const auto k = static_cast<unsigned>(std::countr_zero(hit));
    on_hit(k, t[k], 0.0f, 0.0f);
  }
}

// Sphere `prim` against the `lanes` of a packet, each within its own (tnear, tmax).
template <typename OnHit>
[[gnu::always_inline]] inline void native_hit_lanes(const SphereSet& set, std::uint32_t prim, const RayPacket& packet,
                                                    std::uint32_t lanes, OnHit&& on_hit) {
  hit_lanes(set, prim, packet.lanes(), lanes, on_hit);
}

// Why Embree cannot take the set (a sphere beyond its coordinate range), or nothing.
std::optional<std::string> embree_refusal(const SphereSet& set);

// One user geometry of every sphere in the set (embree_user_geometry.h); `set` must outlive it.
EmbreeGeometry new_embree_geometry(RTCDevice device, const SphereSet& set, RTCBuildQuality quality);

// rtpro's own callbacks decide every sphere hit, so a ray's answer never depends on its packet.
inline bool hits_decided_by_rtpro(const SphereSet&) { return true; }
inline bool packet_lanes_answer_alone(const SphereSet&, bool /*compact*/) { return true; }

}  // namespace rtpro
