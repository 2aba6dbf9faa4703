#pragma once
// The Embree backend's batches: a coherent stream goes to Embree as packets of eight in its own
// layout (rtcIntersectNM), and in scenes without triangles every batch goes as packets of eight
// (rtcIntersect8) whose sphere callbacks decide each hit. Each ray's answer is the single-ray one.
#include "embree_hit_ids.h"
#include "ray_gate.h"
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <embree3/rtcore.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

namespace rtpro {

// What a batch is traced against: the top-level scene, the backend's gate, whether eight
// rays load at once (load_traceable_lanes needs AVX2), and how its ids become rtpro's.
struct EmbreeRayTarget {
  RTCScene scene;
  const RayGate& gate;
  bool wide_loads;
  const EmbreeHitIds& hit_ids;
  const RenderScene& render_scene;  // what the hits' ids name
};

// std::nextafter(t, 0.0f) without the libm call (0.7% of a render): one step towards zero is one
// less in the bit pattern for every non-zero float, infinity (to the largest float) included.
// Never called with NaN (the gate refuses it).
inline float one_step_towards_zero(float t) {
  return t == 0.0f ? t : std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) - 1u);
}

// The next float away from zero for finite positive t; infinity stays infinity.
inline float one_step_away_from_zero(float t) {
  return std::isinf(t) ? t : std::bit_cast<float>(std::bit_cast<std::uint32_t>(t) + 1u);
}

// An answered Embree query as rtpro's hit, or false where it hit nothing.
inline bool from_embree(const RTCRayHit& in, const EmbreeHitIds& hit_ids, Hit& hit) {
  if (in.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = in.ray.tfar;
  hit.u = in.hit.u;
  hit.v = in.hit.v;
  hit.geom_id = in.hit.geomID;
  hit.prim_id = in.hit.primID;
  hit.inst_id = in.hit.instID[0];
  hit_ids.resolve(hit);
  return true;
}

// The closest user-geometry hit so far of a ray that has met none: its tfar.
inline Hit no_user_hit_yet(const Ray& ray) {
  Hit closest;
  closest.t = ray.tfar;
  return closest;
}

// The fields of an Embree ray that come from rtpro's ray, tfar given; time, mask, id and flags are
// the caller's (set once for a whole batch: Embree writes only tfar and the hit).
inline void set_ray_fields(const Ray& ray, float tfar, RTCRay& r) {
  r.org_x = ray.org.x;
  r.org_y = ray.org.y;
  r.org_z = ray.org.z;
  r.tnear = ray.tnear;
  r.dir_x = ray.dir.x;
  r.dir_y = ray.dir.y;
  r.dir_z = ray.dir.z;
  r.tfar = tfar;
}

// Each compiled for AVX2 and for baseline x86-64 (RTPRO_AVX2_CLONES on the definitions). `times`
// holds each ray's time in the shutter (scene/motion.h), or is empty: every ray at time 0.
// One rtcIntersect1 or rtcOccluded1 per ray, whose answer is then the single-ray call's: for
// scattered rays among triangles (see the backend). The context and the ray's constant fields are
// set once per batch, not per ray.
void intersect_one_by_one(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                          std::span<Hit> hits);
void occluded_one_by_one(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                         std::span<std::uint8_t> result);
void intersect_stream(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                      std::span<Hit> hits);
// A segment too short for the open interval (tnear, tfar) is no query: the ray is unoccluded.
void occluded_stream(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                     std::span<std::uint8_t> result);
void intersect_packets(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                       std::span<Hit> hits);
void occluded_packets(const EmbreeRayTarget& target, std::span<const Ray> rays, std::span<const float> times,
                      std::span<std::uint8_t> result);

}  // namespace rtpro
