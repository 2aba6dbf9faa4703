#pragma once
// Eight rays traced through the native BVH together, and the box test for all eight at once.
#include "rtpro/core/bbox.h"
#include "rtpro/core/ray.h"
#include "sphere_lanes.h"

#include <immintrin.h>

#include <cstdint>

namespace rtpro {

// Eight rays traced through a BVH together (scattered rays of a batch start close to each other
// and go the same way often enough), laid out as Embree lays out its packets so the sphere test of
// sphere_lanes.h applies. `tmax` is each lane's closest hit so far (or its tfar for occlusion).
constexpr unsigned kPacketSize = 8;

struct RayPacket {
  alignas(32) float org_x[kPacketSize], org_y[kPacketSize], org_z[kPacketSize];
  alignas(32) float dir_x[kPacketSize], dir_y[kPacketSize], dir_z[kPacketSize];
  alignas(32) float inv_x[kPacketSize], inv_y[kPacketSize], inv_z[kPacketSize];
  alignas(32) float tnear[kPacketSize], tmax[kPacketSize];
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
    const __m256 one = _mm256_set1_ps(1.0f);
    _mm256_store_ps(inv_x, _mm256_div_ps(one, _mm256_load_ps(dir_x)));
    _mm256_store_ps(inv_y, _mm256_div_ps(one, _mm256_load_ps(dir_y)));
    _mm256_store_ps(inv_z, _mm256_div_ps(one, _mm256_load_ps(dir_z)));
  }
  RayLanes lanes() const { return {org_x, org_y, org_z, dir_x, dir_y, dir_z, tnear, tmax, kPacketSize}; }
};

// One axis of the slab test for eight lanes, in hits_box's operand order: a NaN axis (0·∞) leaves
// `near` at tnear and `far` at tmax.
[[gnu::target("avx2")]] inline void packet_slab(float lower, float upper, const float* org, const float* inv,
                                                __m256 tnear, __m256 tmax, __m256& near, __m256& far) {
  constexpr float kRoundingSlack = 1.0f + 2.0f * (3.0f * 0x1p-24f) / (1.0f - 3.0f * 0x1p-24f);
  const __m256 o = _mm256_load_ps(org), i = _mm256_load_ps(inv);
  const __m256 tn = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(lower), o), i);
  const __m256 tf = _mm256_mul_ps(_mm256_sub_ps(_mm256_set1_ps(upper), o), i);
  near = _mm256_max_ps(_mm256_min_ps(tf, tn), tnear);
  far = _mm256_min_ps(_mm256_mul_ps(_mm256_max_ps(tn, tf), _mm256_set1_ps(kRoundingSlack)), tmax);
}

// hits_box for the eight lanes at once, the same slab arithmetic lane by lane.
[[gnu::target("avx2")]] inline std::uint32_t packet_hits_box(const BBox& box, const RayPacket& p) {
  const __m256 tnear = _mm256_load_ps(p.tnear);
  const __m256 tmax = _mm256_load_ps(p.tmax);
  __m256 nx, fx, ny, fy, nz, fz;
  packet_slab(box.lower.x, box.upper.x, p.org_x, p.inv_x, tnear, tmax, nx, fx);
  packet_slab(box.lower.y, box.upper.y, p.org_y, p.inv_y, tnear, tmax, ny, fy);
  packet_slab(box.lower.z, box.upper.z, p.org_z, p.inv_z, tnear, tmax, nz, fz);
  const __m256 near = _mm256_max_ps(_mm256_max_ps(nx, ny), nz);
  const __m256 far = _mm256_min_ps(_mm256_min_ps(fx, fy), fz);
  return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_cmp_ps(near, far, _CMP_LE_OQ)));
}

}  // namespace rtpro
