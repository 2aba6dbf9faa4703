#pragma once
// Eight rays traced through the native BVH together, and the box test for all eight at once.
#include "rtpro/core/bbox.h"
#include "rtpro/core/ray.h"
#include "sphere_lanes.h"

#include <immintrin.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace rtpro {

// Eight rays traced through a BVH together (scattered rays of a batch start close to each other
// and go the same way often enough), laid out as Embree lays out its packets so the sphere test of
// sphere_lanes.h applies. `tmax` is each lane's closest hit so far (or its tfar for occlusion).
constexpr unsigned kPacketSize = 8;

// Lanes whose coordinate is within_traceable_range: |v| < the limit is false for NaN and infinity.
[[gnu::target("avx2")]] inline __m256 lanes_in_traceable_range(__m256 v) {
  return _mm256_cmp_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), v), _mm256_set1_ps(kMaxTraceableMagnitude), _CMP_LT_OQ);
}

// Floats [4·half, 4·half + 4) of rays k and k + 4 (of eight consecutive rays at `f`), one per
// 128-bit half.
[[gnu::target("avx2")]] inline __m256 ray_halves(const float* f, int k, int half) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(f + 8 * k + 4 * half)),
                              _mm_loadu_ps(f + 8 * (k + 4) + 4 * half), 1);
}

// Eight consecutive rays at once, for the packets of both backends: an 8x8 transpose of their
// fields (a Ray is eight floats) into `fields` (org x, y, z, tnear, dir x, y, z, tfar: a Ray's own
// order), in place of 64 scalar stores, and the backends' admission test (is_traceable) lane by
// lane. Returns false, writing nothing, when any of the eight is not traceable: the caller then
// takes them one by one through RayGate, so that rejected rays are counted as ever.
[[gnu::target("avx2"), gnu::always_inline]] inline bool transpose_traceable_lanes(const Ray* eight,
                                                                                  float* const (&fields)[8]) {
  static_assert(sizeof(Ray) == 8 * sizeof(float) && offsetof(Ray, tnear) == 3 * sizeof(float) &&
                offsetof(Ray, dir) == 4 * sizeof(float) && offsetof(Ray, tfar) == 7 * sizeof(float));
  // Rays k and k + 4 share a register, one in each 128-bit half, so the transpose is two 4x4
  // transposes within halves. 128-bit loads: a 256-bit array spilled to the stack was reloaded
  // over the halves' stores (a store-forwarding stall per group).
  const float* f = reinterpret_cast<const float*>(eight);
  const __m256 a0 = ray_halves(f, 0, 0), a1 = ray_halves(f, 1, 0), a2 = ray_halves(f, 2, 0), a3 = ray_halves(f, 3, 0);
  const __m256 b0 = ray_halves(f, 0, 1), b1 = ray_halves(f, 1, 1), b2 = ray_halves(f, 2, 1), b3 = ray_halves(f, 3, 1);
  const __m256 s0 = _mm256_unpacklo_ps(a0, a1), s1 = _mm256_unpackhi_ps(a0, a1);
  const __m256 s2 = _mm256_unpacklo_ps(a2, a3), s3 = _mm256_unpackhi_ps(a2, a3);
  const __m256 e0 = _mm256_unpacklo_ps(b0, b1), e1 = _mm256_unpackhi_ps(b0, b1);
  const __m256 e2 = _mm256_unpacklo_ps(b2, b3), e3 = _mm256_unpackhi_ps(b2, b3);
  const __m256 ox = _mm256_shuffle_ps(s0, s2, 0x44), oy = _mm256_shuffle_ps(s0, s2, 0xEE);
  const __m256 oz = _mm256_shuffle_ps(s1, s3, 0x44), tn = _mm256_shuffle_ps(s1, s3, 0xEE);
  const __m256 dx = _mm256_shuffle_ps(e0, e2, 0x44), dy = _mm256_shuffle_ps(e0, e2, 0xEE);
  const __m256 dz = _mm256_shuffle_ps(e1, e3, 0x44), tf = _mm256_shuffle_ps(e1, e3, 0xEE);

  // is_traceable, lane by lane: ordered comparisons are false for NaN, as the scalar tests are.
  const __m256 zero = _mm256_setzero_ps();
  const __m256 infinity = _mm256_set1_ps(std::numeric_limits<float>::infinity());
  __m256 ok = _mm256_and_ps(lanes_in_traceable_range(ox), lanes_in_traceable_range(oy));
  ok = _mm256_and_ps(ok, _mm256_and_ps(lanes_in_traceable_range(oz), lanes_in_traceable_range(dx)));
  ok = _mm256_and_ps(ok, _mm256_and_ps(lanes_in_traceable_range(dy), lanes_in_traceable_range(dz)));
  const __m256 x_or_y = _mm256_or_ps(_mm256_cmp_ps(dx, zero, _CMP_NEQ_OQ), _mm256_cmp_ps(dy, zero, _CMP_NEQ_OQ));
  ok = _mm256_and_ps(ok, _mm256_or_ps(x_or_y, _mm256_cmp_ps(dz, zero, _CMP_NEQ_OQ)));
  ok = _mm256_and_ps(ok, _mm256_cmp_ps(_mm256_andnot_ps(_mm256_set1_ps(-0.0f), tn), infinity, _CMP_LT_OQ));
  ok = _mm256_and_ps(ok, _mm256_cmp_ps(tf, tf, _CMP_ORD_Q));
  ok = _mm256_and_ps(ok, _mm256_and_ps(_mm256_cmp_ps(tn, zero, _CMP_GE_OQ), _mm256_cmp_ps(tn, tf, _CMP_LE_OQ)));
  if (_mm256_movemask_ps(ok) != 0xFF) return false;

  const __m256 rows[8] = {ox, oy, oz, tn, dx, dy, dz, tf};
  for (int k = 0; k < 8; ++k) _mm256_storeu_ps(fields[k], rows[k]);
  return true;
}

// transpose_traceable_lanes for callers that also have a baseline clone, which an always-inline
// AVX2 function cannot be inlined into. RayPacket inlines the transpose itself: out of line, with
// the fields reached through the pointer array, it cost the native backend's sphere packets 1.1%
// of the Whitted demo's instructions.
[[gnu::target("avx2")]] inline bool load_traceable_lanes(const Ray* eight, float* const (&fields)[8]) {
  return transpose_traceable_lanes(eight, fields);
}

struct RayPacket {
  alignas(32) float org_x[kPacketSize], org_y[kPacketSize], org_z[kPacketSize];
  alignas(32) float dir_x[kPacketSize], dir_y[kPacketSize], dir_z[kPacketSize];
  alignas(32) float inv_x[kPacketSize], inv_y[kPacketSize], inv_z[kPacketSize];
  alignas(32) float tnear[kPacketSize], tmax[kPacketSize];
  // Each lane's time in the shutter (scene/motion.h), read only by a traversal with times.
  alignas(32) float time[kPacketSize] = {};
  const Ray* rays[kPacketSize];

  void set(unsigned lane, const Ray& ray, float t_max) {
    org_x[lane] = ray.org.x;
    org_y[lane] = ray.org.y;
    org_z[lane] = ray.org.z;
    dir_x[lane] = ray.dir.x;
    dir_y[lane] = ray.dir.y;
    dir_z[lane] = ray.dir.z;
    tnear[lane] = ray.tnear;
    tmax[lane] = t_max;
    rays[lane] = &ray;
  }
  // Lanes past the last ray become copies of lane 0, never active, so every lane holds finite
  // values; then the reciprocal directions of all eight lanes in one division each (IEEE division,
  // the very 1.0f / d of the single-ray code).
  [[gnu::target("avx2")]] void finish(unsigned count) {
    for (unsigned lane = count; lane < kPacketSize; ++lane) set(lane, *rays[0], tmax[0]);
    reciprocals();
  }
  // Lanes outside `active` (not 0) become copies of its first lane, never active; then the
  // reciprocal directions, as finish does.
  [[gnu::target("avx2")]] void finish_lanes(std::uint32_t active) {
    const auto first = static_cast<unsigned>(std::countr_zero(active));
    for (unsigned lane = 0; lane < kPacketSize; ++lane)
      if ((active >> lane & 1u) == 0) {
        set(lane, *rays[first], tmax[first]);
        time[lane] = time[first];
      }
    reciprocals();
  }
  // Eight consecutive rays, if all are traceable (load_traceable_lanes); the packet is then
  // finished (as by finish(8)).
  [[gnu::target("avx2")]] bool load_traceable(const Ray* eight) {
    if (!transpose_traceable_lanes(eight, {org_x, org_y, org_z, tnear, dir_x, dir_y, dir_z, tmax})) return false;
    for (unsigned lane = 0; lane < kPacketSize; ++lane) rays[lane] = eight + lane;
    reciprocals();
    return true;
  }

  RayLanes lanes() const { return {org_x, org_y, org_z, dir_x, dir_y, dir_z, tnear, tmax, kPacketSize}; }

 private:
  [[gnu::target("avx2")]] void reciprocals() {
    const __m256 one = _mm256_set1_ps(1.0f);
    _mm256_store_ps(inv_x, _mm256_div_ps(one, _mm256_load_ps(dir_x)));
    _mm256_store_ps(inv_y, _mm256_div_ps(one, _mm256_load_ps(dir_y)));
    _mm256_store_ps(inv_z, _mm256_div_ps(one, _mm256_load_ps(dir_z)));
  }
};

// One axis of the slab test for eight lanes, in hits_box's operand order: a NaN axis (0·∞) leaves
// `near` at tnear and `far` at tmax.
[[gnu::target("avx2")]] inline void packet_slab(__m256 lower, __m256 upper, const float* org, const float* inv,
                                                __m256 tnear, __m256 tmax, __m256& near, __m256& far) {
  constexpr float kRoundingSlack = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  const __m256 o = _mm256_load_ps(org), i = _mm256_load_ps(inv);
  const __m256 tn = _mm256_mul_ps(_mm256_sub_ps(lower, o), i);
  const __m256 tf = _mm256_mul_ps(_mm256_sub_ps(upper, o), i);
  near = _mm256_max_ps(_mm256_min_ps(tf, tn), tnear);
  far = _mm256_min_ps(_mm256_mul_ps(_mm256_max_ps(tn, tf), _mm256_set1_ps(kRoundingSlack)), tmax);
}

// hits_box for the eight lanes at once, the same slab arithmetic lane by lane.
[[gnu::target("avx2")]] inline std::uint32_t packet_hits_box(const BBox& box, const RayPacket& p) {
  const __m256 tnear = _mm256_load_ps(p.tnear);
  const __m256 tmax = _mm256_load_ps(p.tmax);
  __m256 nx, fx, ny, fy, nz, fz;
  packet_slab(_mm256_set1_ps(box.lower.x), _mm256_set1_ps(box.upper.x), p.org_x, p.inv_x, tnear, tmax, nx, fx);
  packet_slab(_mm256_set1_ps(box.lower.y), _mm256_set1_ps(box.upper.y), p.org_y, p.inv_y, tnear, tmax, ny, fy);
  packet_slab(_mm256_set1_ps(box.lower.z), _mm256_set1_ps(box.upper.z), p.org_z, p.inv_z, tnear, tmax, nz, fz);
  const __m256 near = _mm256_max_ps(_mm256_max_ps(nx, ny), nz);
  const __m256 far = _mm256_min_ps(_mm256_min_ps(fx, fy), fz);
  return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(near, far, _CMP_LE_OQ)));
}

// A coordinate moving from a to b at each lane's time: LinearBounds::at's a + t·(b − a).
[[gnu::target("avx2"), gnu::always_inline]] inline __m256 lanes_at(__m256 time, float a, float b) {
  return _mm256_add_ps(_mm256_set1_ps(a), _mm256_mul_ps(time, _mm256_set1_ps(b - a)));
}

// packet_hits_box of a box moving from `open` to `close`, each lane against it at the lane's time.
[[gnu::target("avx2")]] inline std::uint32_t packet_hits_moving_box(const BBox& open, const BBox& close,
                                                                    const RayPacket& p) {
  const __m256 tnear = _mm256_load_ps(p.tnear);
  const __m256 tmax = _mm256_load_ps(p.tmax);
  const __m256 time = _mm256_load_ps(p.time);
  __m256 nx, fx, ny, fy, nz, fz;
  packet_slab(lanes_at(time, open.lower.x, close.lower.x), lanes_at(time, open.upper.x, close.upper.x), p.org_x,
              p.inv_x, tnear, tmax, nx, fx);
  packet_slab(lanes_at(time, open.lower.y, close.lower.y), lanes_at(time, open.upper.y, close.upper.y), p.org_y,
              p.inv_y, tnear, tmax, ny, fy);
  packet_slab(lanes_at(time, open.lower.z, close.lower.z), lanes_at(time, open.upper.z, close.upper.z), p.org_z,
              p.inv_z, tnear, tmax, nz, fz);
  const __m256 near = _mm256_max_ps(_mm256_max_ps(nx, ny), nz);
  const __m256 far = _mm256_min_ps(_mm256_min_ps(fx, fy), fz);
  return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(near, far, _CMP_LE_OQ)));
}

}  // namespace rtpro
