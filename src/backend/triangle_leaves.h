#pragma once
// The native BVH's triangle leaves tested four triangles at a time, their vertices copied into
// rows that load as lanes (Embree's triangle4 layout, without its empty slots): in the packets of
// scattered rays one or two lanes enter a leaf, and the triangles rather than the rays are what
// there are several of. The block test is intersect_triangle's own double-precision arithmetic,
// operation for operation, in the four lanes of AVX2 registers: the same hits to the bit, so
// images do not depend on whether a leaf is tested so.
#include "bvh.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <immintrin.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtpro {

inline constexpr unsigned kBlockWidth = 4;

// The vertices of every reference of one BVH, in the BVH's reference order, as nine rows of
// floats (row 3·vertex + coordinate), each `stride` long: a leaf's references are consecutive
// columns, so four of them load as four consecutive floats of each row (columns past the leaf's
// end belong to the next leaves, or to the zero columns at the end, and are masked off). 36 bytes
// a reference; one that is not a triangle has zeros. A leaf whose references are all triangles
// that keep still is marked kStillRows in triangle_leaf (per node); a tree with no such leaf has
// no rows.
// Deforming meshes (scene/motion.h) have rows of their own, nine per time step in
// `motion_vertices` (step s's rows from s · 9 · stride), for the step count of the first deforming
// mesh of the group: a leaf whose references are all triangles of meshes with that many steps is
// marked kMovingRows, and a ray tests it at its time, each block's two steps interpolated as the
// meshes interpolate their vertices (TriangleMesh::vertex_at). 36 bytes a reference per step.
inline constexpr std::uint8_t kStillRows = 1;
inline constexpr std::uint8_t kMovingRows = 2;

struct TriangleLeaves {
  std::size_t stride = 0;
  std::vector<float, HugePageAllocator<float>> vertices;
  std::uint32_t motion_steps = 0;
  std::vector<float, HugePageAllocator<float>> motion_vertices;
  std::vector<std::uint8_t> triangle_leaf;

  const float* column(std::uint32_t ref) const { return vertices.data() + ref; }
  const float* motion_column(std::uint32_t step, std::uint32_t ref) const {
    return motion_vertices.data() + std::size_t{step} * 9 * stride + ref;
  }
  std::size_t memory_bytes() const {
    return (vertices.capacity() + motion_vertices.capacity()) * sizeof(float) +
           triangle_leaf.capacity() * sizeof(std::uint8_t);
  }
};

// With `enabled` false (the CPU has no AVX2), no leaf is marked and no vertex copied.
TriangleLeaves build_triangle_leaves(const Group& group, const Bvh& bvh, bool enabled = true);

// The slots' hits, where bit j of the returned mask is set.
struct BlockHits {
  alignas(16) float t[kBlockWidth], u[kBlockWidth], v[kBlockWidth];
};

// One ray's origin and direction widened to double and broadcast over the lanes once per ray.
struct BlockRay {
  __m256d org[3], dir[3];
  float tnear;
};

[[gnu::target("avx2")]] inline BlockRay block_ray(const Vec3& org, const Vec3& dir, float tnear) {
  return {{_mm256_set1_pd(org.x), _mm256_set1_pd(org.y), _mm256_set1_pd(org.z)},
          {_mm256_set1_pd(dir.x), _mm256_set1_pd(dir.y), _mm256_set1_pd(dir.z)},
          tnear};
}

// Four consecutive columns of the nine rows: row 3·vertex + coordinate.
struct BlockVertices {
  __m128 row[9];
};

[[gnu::target("avx2"), gnu::always_inline]] inline BlockVertices load_block(const float* first, std::size_t stride) {
  BlockVertices block;
  for (std::size_t k = 0; k < 9; ++k) block.row[k] = _mm_loadu_ps(first + k * stride);
  return block;
}

// The columns between two steps' rows (`first` in the earlier step's, the later step's nine rows
// after them) at `fraction` of the way: motion_lerp's (1 − f)·a + f·b, operation for operation.
[[gnu::target("avx2"), gnu::always_inline]] inline BlockVertices load_block_between(const float* first,
                                                                                    std::size_t stride,
                                                                                    float fraction) {
  const __m128 f = _mm_set1_ps(fraction), rest = _mm_set1_ps(1.0f - fraction);
  BlockVertices block;
  for (std::size_t k = 0; k < 9; ++k)
    block.row[k] = _mm_add_ps(_mm_mul_ps(rest, _mm_loadu_ps(first + k * stride)),
                              _mm_mul_ps(f, _mm_loadu_ps(first + (9 + k) * stride)));
  return block;
}

// intersect_triangle for four triangles at once, those of `slots` (bit j: column j of `block`),
// each within (ray.tnear, tfar]: the mask of slots it accepts, their distances and barycentrics in
// `hits`.
[[gnu::target("avx2"), gnu::always_inline]] inline unsigned intersect_block(const BlockVertices& block, unsigned slots,
                                                                            const BlockRay& ray, float tfar,
                                                                            BlockHits& hits) {
  const auto sub = _mm256_sub_pd;
  const auto mul = _mm256_mul_pd;
  const auto add = _mm256_add_pd;
  __m256d p0[3], e1[3], e2[3];
  for (int c = 0; c < 3; ++c) {
    p0[c] = _mm256_cvtps_pd(block.row[c]);
    e1[c] = sub(_mm256_cvtps_pd(block.row[3 + c]), p0[c]);
    e2[c] = sub(_mm256_cvtps_pd(block.row[6 + c]), p0[c]);
  }
  const __m256d* d = ray.dir;
  const __m256d px = sub(mul(d[1], e2[2]), mul(d[2], e2[1]));
  const __m256d py = sub(mul(d[2], e2[0]), mul(d[0], e2[2]));
  const __m256d pz = sub(mul(d[0], e2[1]), mul(d[1], e2[0]));
  const __m256d det = add(add(mul(e1[0], px), mul(e1[1], py)), mul(e1[2], pz));
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const __m256d inv_det = _mm256_div_pd(one, det);

  const __m256d sx = sub(ray.org[0], p0[0]), sy = sub(ray.org[1], p0[1]), sz = sub(ray.org[2], p0[2]);
  const __m256d u = mul(add(add(mul(sx, px), mul(sy, py)), mul(sz, pz)), inv_det);
  const __m256d qx = sub(mul(sy, e1[2]), mul(sz, e1[1]));
  const __m256d qy = sub(mul(sz, e1[0]), mul(sx, e1[2]));
  const __m256d qz = sub(mul(sx, e1[1]), mul(sy, e1[0]));
  const __m256d v = mul(add(add(mul(d[0], qx), mul(d[1], qy)), mul(d[2], qz)), inv_det);
  const __m256d t = mul(add(add(mul(e2[0], qx), mul(e2[1], qy)), mul(e2[2], qz)), inv_det);

  // The scalar test's rejections, each an ordered comparison (false for NaN) as there.
  __m256d rejected = _mm256_cmp_pd(det, zero, _CMP_EQ_OQ);
  rejected = _mm256_or_pd(rejected, _mm256_cmp_pd(u, zero, _CMP_LT_OQ));
  rejected = _mm256_or_pd(rejected, _mm256_cmp_pd(u, one, _CMP_GT_OQ));
  rejected = _mm256_or_pd(rejected, _mm256_cmp_pd(v, zero, _CMP_LT_OQ));
  rejected = _mm256_or_pd(rejected, _mm256_cmp_pd(add(u, v), one, _CMP_GT_OQ));
  const __m128 t_float = _mm256_cvtpd_ps(t);
  const __m128 in_range =
      _mm_and_ps(_mm_cmpgt_ps(t_float, _mm_set1_ps(ray.tnear)), _mm_cmple_ps(t_float, _mm_set1_ps(tfar)));
  const unsigned mask =
      static_cast<unsigned>(_mm_movemask_ps(in_range)) & ~static_cast<unsigned>(_mm256_movemask_pd(rejected)) & slots;
  if (mask != 0) {
    _mm_store_ps(hits.t, t_float);
    _mm_store_ps(hits.u, _mm256_cvtpd_ps(u));
    _mm_store_ps(hits.v, _mm256_cvtpd_ps(v));
  }
  return mask;
}

}  // namespace rtpro
