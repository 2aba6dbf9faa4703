#pragma once
// A kind of shape that Embree intersects through rtpro's own callbacks (a user geometry), so that
// its hits are bit-identical between the backends: one user geometry holds every primitive of a
// set, and the callbacks here do all that is not the shape's, for any kind. A kind supplies, beside
// the scene side's primitive_count_of and primitive_bounds_of:
//   hit_lanes(shapes, prim, lanes, active, on_hit)   on_hit(k, t, u, v) for every active lane k
//       of `lanes` that meets primitive `prim` within its closed [tnear, tfar], in lane order
//   hits_decided_by_rtpro(shapes) returning true     (backend_shapes.h)
// and its two callbacks compiled for AVX2 and the baseline, each one line (sphere_backend.cpp):
// Clang 14 does not multiversion a function template, so the clones cannot be made here.
//
// Equal distances follow the shared tie rule (is_closer in hit.h): the lower (instance, geometry,
// primitive) wins. Embree leaves the hit record undefined inside callbacks, so the closest
// user-geometry hit of each ray is kept beside it, in a context that extends RTCIntersectContext.
#include "embree_handles.h"
#include "sphere_lanes.h"
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "shape_hit.h"

#include <embree3/rtcore.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace rtpro {

struct EmbreeIntersectContext {
  RTCIntersectContext base;  // first member: Embree passes &base to the callbacks
  // The closest user-geometry hit of each ray of the query so far, indexed by RTCRay::id. Each
  // starts as Hit{.t = ray.tfar} with invalid ids, so a hit exactly at tfar is accepted as
  // (tnear, tfar] promises.
  Hit* closest_user_hits;
};
static_assert(std::is_standard_layout_v<EmbreeIntersectContext>);

// The rays of a packet (or the one ray of rtcIntersect1/rtcOccluded1) that Embree asks about.
[[gnu::always_inline]] inline RayLanes lanes_of(RTCRayN* rays, unsigned n) {
  float* base = reinterpret_cast<float*>(rays);
  // RTCRayN is a structure of arrays: org_x[n], org_y[n], org_z[n], tnear[n], dir_x[n], ...
  return {base, base + n, base + 2 * n, base + 4 * n, base + 5 * n, base + 6 * n, base + 3 * n, base + 8 * n, n};
}

// The lanes Embree marks valid (-1), as a bit mask. Out of line: inlined, its loop for other
// packet sizes is vectorised into the callbacks, which then realign their stack on every call.
std::uint32_t valid_lanes(const int* valid, unsigned n);

// A moving kind's primitive against each valid lane at the lane's own time, one by one with the
// kind's native_hit_at: the native traversal's test, so both backends agree bit for bit.
template <typename Shapes, typename OnHit>
void moving_hit_lanes(const Shapes& shapes, std::uint32_t prim, RTCRayN* rays, unsigned n, const int* valid,
                      OnHit&& on_hit) {
  for (std::uint32_t lanes = valid_lanes(valid, n); lanes != 0; lanes &= lanes - 1) {
    const auto i = static_cast<unsigned>(std::countr_zero(lanes));
    const Ray ray{{RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)},
                  RTCRayN_tnear(rays, n, i),
                  {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)},
                  RTCRayN_tfar(rays, n, i)};
    ShapeHit hit;
    if (native_hit_at(shapes, prim, ray, RTCRayN_time(rays, n, i), ray.tfar, hit)) on_hit(i, hit.t, hit.u, hit.v);
  }
}

// One ulp outwards: the bounds are rounded to nearest, and a box even slightly too small would let
// Embree cull grazing hits that the kind's hit_lanes finds.
template <typename Shapes>
void bound_user_primitive(const RTCBoundsFunctionArguments* args) {
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  const Shapes& shapes = *static_cast<const Shapes*>(args->geometryUserPtr);
  BBox box;
  if constexpr (requires { shapes.moving(); })
    box = shapes.moving() ? primitive_bounds_at_step(shapes, args->primID, args->timeStep)
                          : primitive_bounds_of(shapes, args->primID);
  else box = primitive_bounds_of(shapes, args->primID);
  RTCBounds& out = *args->bounds_o;
  out.lower_x = std::nextafter(box.lower.x, -kInfinity);
  out.lower_y = std::nextafter(box.lower.y, -kInfinity);
  out.lower_z = std::nextafter(box.lower.z, -kInfinity);
  out.upper_x = std::nextafter(box.upper.x, kInfinity);
  out.upper_y = std::nextafter(box.upper.y, kInfinity);
  out.upper_z = std::nextafter(box.upper.z, kInfinity);
}

// Embree calls this with the ray in the primitive's own space (already transformed when
// instanced) and tfar = the closest hit so far; the hit part is undefined and is never read. A
// distance equal to tfar wins only over an equal-distance user-geometry hit with a higher (inst,
// geom, prim) key — which the context remembers — never over a triangle that Embree accepted at
// that distance.
template <typename Shapes>
[[gnu::always_inline]] inline void intersect_user_primitive(const RTCIntersectFunctionNArguments* args) {
  const Shapes& shapes = *static_cast<const Shapes*>(args->geometryUserPtr);
  Hit* const closest_user_hits = reinterpret_cast<const EmbreeIntersectContext*>(args->context)->closest_user_hits;
  const std::uint32_t inst = args->context->instID[0];
  const unsigned n = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
  const auto on_hit = [&](unsigned i, float t, float u, float v) {
    float& tfar = RTCRayN_tfar(rays, n, i);
    Hit& closest = closest_user_hits[RTCRayN_id(rays, n, i)];
    const bool wins_tie = t == closest.t && is_closer(t, inst, args->geomID, args->primID, closest, closest.t);
    if (!(t < tfar || wins_tie)) return;

    closest.t = t;
    closest.inst_id = inst;
    closest.geom_id = args->geomID;
    closest.prim_id = args->primID;

    tfar = t;
    // Ng is left unset: Embree does not read it, and neither does rtpro (hit_of_lane).
    RTCHitN_u(hits, n, i) = u;
    RTCHitN_v(hits, n, i) = v;
    RTCHitN_primID(hits, n, i) = args->primID;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = inst;
  };
  if constexpr (requires { shapes.moving(); })
    if (shapes.moving()) return moving_hit_lanes(shapes, args->primID, rays, n, args->valid, on_hit);
  hit_lanes(shapes, args->primID, lanes_of(rays, n), valid_lanes(args->valid, n), on_hit);
}

// Occlusion queries arrive with tfar already lowered by one ulp (see the backend), so the closed
// interval of hit_lanes here is exactly the open (tnear, tfar) of Backend::occluded.
template <typename Shapes>
[[gnu::always_inline]] inline void occlude_user_primitive(const RTCOccludedFunctionNArguments* args) {
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  const unsigned n = args->N;
  RTCRayN* rays = args->ray;
  const Shapes& shapes = *static_cast<const Shapes*>(args->geometryUserPtr);
  const auto on_hit = [&](unsigned i, float, float, float) { RTCRayN_tfar(rays, n, i) = -kInfinity; };
  if constexpr (requires { shapes.moving(); })
    if (shapes.moving()) return moving_hit_lanes(shapes, args->primID, rays, n, args->valid, on_hit);
  hit_lanes(shapes, args->primID, lanes_of(rays, n), valid_lanes(args->valid, n), on_hit);
}

// A committed user geometry over `shapes`, which must outlive it, answered by `intersect` and
// `occlude` (the kind's clones of intersect_user_primitive and occlude_user_primitive). Queries
// through it must pass an EmbreeIntersectContext to rtcIntersect*; plain contexts suffice for
// rtcOccluded*.
template <typename Shapes>
EmbreeGeometry new_embree_user_geometry(RTCDevice device, const Shapes& shapes, RTCBuildQuality quality,
                                        RTCIntersectFunctionN intersect, RTCOccludedFunctionN occlude) {
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  rtcSetGeometryUserPrimitiveCount(g, primitive_count_of(shapes));
  if constexpr (requires { shapes.moving(); })
    if (shapes.moving()) rtcSetGeometryTimeStepCount(g, shapes.step_count);
  // Embree 3.13.5 ignores the bounds function's own user pointer and passes the geometry's.
  rtcSetGeometryUserData(g, const_cast<Shapes*>(&shapes));
  rtcSetGeometryBoundsFunction(g, &bound_user_primitive<Shapes>, nullptr);
  rtcSetGeometryIntersectFunction(g, intersect);
  rtcSetGeometryOccludedFunction(g, occlude);
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  return geometry;
}

}  // namespace rtpro
