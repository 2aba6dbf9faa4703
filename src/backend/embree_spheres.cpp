#include "embree_spheres.h"

#include "rtpro/core/avx2_clones.h"
#include "rtpro/geometry/sphere_intersect.h"
#include "sphere_lanes.h"

#include <emmintrin.h>

#include <bit>
#include <cmath>
#include <limits>

namespace rtpro {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// One ulp outwards: centre ± radius is rounded to nearest, and a box even slightly too small
// would let Embree cull grazing hits that intersect_sphere finds.
void bound_sphere(const RTCBoundsFunctionArguments* args) {
  const BBox box = static_cast<const SphereSet*>(args->geometryUserPtr)->sphere_bounds(args->primID);
  RTCBounds& out = *args->bounds_o;
  out.lower_x = std::nextafter(box.lower.x, -kInfinity);
  out.lower_y = std::nextafter(box.lower.y, -kInfinity);
  out.lower_z = std::nextafter(box.lower.z, -kInfinity);
  out.upper_x = std::nextafter(box.upper.x, kInfinity);
  out.upper_y = std::nextafter(box.upper.y, kInfinity);
  out.upper_z = std::nextafter(box.upper.z, kInfinity);
}

// The rays of a packet (or the one ray of rtcIntersect1/rtcOccluded1) that Embree asks about.
RayLanes lanes_of(RTCRayN* rays, unsigned n) {
  float* base = reinterpret_cast<float*>(rays);
  // RTCRayN is a structure of arrays: org_x[n], org_y[n], org_z[n], tnear[n], dir_x[n], ...
  return {base, base + n, base + 2 * n, base + 4 * n, base + 5 * n, base + 6 * n, base + 3 * n, base + 8 * n, n};
}

RTPRO_AVX2_CLONES std::uint32_t valid_lanes(const int* valid, unsigned n) {
  if (n == 8) {  // Embree's packets of eight: one compare
    const __m128i minus_one = _mm_set1_epi32(-1);
    const __m128i low = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(valid)), minus_one);
    const __m128i high = _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(valid + 4)), minus_one);
    return static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(low)) | _mm_movemask_ps(_mm_castsi128_ps(high))
                                                                                   << 4);
  }
  std::uint32_t active = 0;
  for (unsigned i = 0; i < n; ++i)
    if (valid[i] == -1) active |= 1u << i;
  return active;
}

// Embree calls this with the ray in the sphere's own space (already transformed when instanced)
// and tfar = the closest hit so far; the hit part is undefined and is never read. A distance
// equal to tfar wins only over an equal-distance sphere with a higher (inst, geom, prim) key —
// which the context remembers — never over a triangle that Embree accepted at that distance.
RTPRO_AVX2_CLONES
void intersect_spheres(const RTCIntersectFunctionNArguments* args) {
  const Sphere& sphere = static_cast<const SphereSet*>(args->geometryUserPtr)->spheres[args->primID];
  Hit* const closest_spheres = reinterpret_cast<const EmbreeIntersectContext*>(args->context)->closest_spheres;
  const std::uint32_t inst = args->context->instID[0];
  const unsigned n = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);

  float distances[32];
  std::uint32_t found =
      intersect_sphere_lanes(sphere.center, sphere.radius, lanes_of(rays, n), valid_lanes(args->valid, n), distances);
  for (; found != 0; found &= found - 1) {
    const auto i = static_cast<unsigned>(std::countr_zero(found));
    const float t = distances[i];
    float& tfar = RTCRayN_tfar(rays, n, i);
    Hit& closest = closest_spheres[RTCRayN_id(rays, n, i)];
    const bool wins_tie = t == closest.t && is_closer(t, inst, args->geomID, args->primID, closest, closest.t);
    if (!(t < tfar || wins_tie)) continue;

    closest.t = t;
    closest.inst_id = inst;
    closest.geom_id = args->geomID;
    closest.prim_id = args->primID;

    tfar = t;
    // Ng is left unset: Embree does not read it, and neither does rtpro (hit_of_lane).
    RTCHitN_u(hits, n, i) = 0.0f;
    RTCHitN_v(hits, n, i) = 0.0f;
    RTCHitN_primID(hits, n, i) = args->primID;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = inst;
  }
}

// Occlusion queries arrive with tfar already lowered by one ulp (see the backend), so the closed
// interval of intersect_sphere here is exactly the open (tnear, tfar) of Backend::occluded.
RTPRO_AVX2_CLONES
void occlude_spheres(const RTCOccludedFunctionNArguments* args) {
  const Sphere& sphere = static_cast<const SphereSet*>(args->geometryUserPtr)->spheres[args->primID];
  const unsigned n = args->N;
  RTCRayN* rays = args->ray;
  float distances[32];
  std::uint32_t found =
      intersect_sphere_lanes(sphere.center, sphere.radius, lanes_of(rays, n), valid_lanes(args->valid, n), distances);
  for (; found != 0; found &= found - 1)
    RTCRayN_tfar(rays, n, static_cast<unsigned>(std::countr_zero(found))) = -kInfinity;
}

}  // namespace

EmbreeGeometry new_embree_sphere_geometry(RTCDevice device, const SphereSet& spheres, RTCBuildQuality quality) {
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  rtcSetGeometryUserPrimitiveCount(g, static_cast<unsigned>(spheres.spheres.size()));
  // Embree 3.13.5 ignores the bounds function's own user pointer and passes the geometry's.
  rtcSetGeometryUserData(g, const_cast<SphereSet*>(&spheres));
  rtcSetGeometryBoundsFunction(g, &bound_sphere, nullptr);
  rtcSetGeometryIntersectFunction(g, &intersect_spheres);
  rtcSetGeometryOccludedFunction(g, &occlude_spheres);
  rtcSetGeometryBuildQuality(g, quality);
  rtcCommitGeometry(g);
  return geometry;
}

}  // namespace rtpro
