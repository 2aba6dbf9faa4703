#pragma once
// Four 3-vectors in SSE2 registers, a coordinate a register, and the few operations that the
// four-at-a-time shading kernels (point_light_lanes, make_sphere_surfaces4) share. Each operation
// is the scalar Vec3 one lane by lane, in the same order (dot sums x, y, z left to right), so
// lanes compute exactly what the scalar code computes.
#include "rtpro/core/vec3.h"

#include <emmintrin.h>
#include <xmmintrin.h>

namespace rtpro::lanes {

struct Lanes3 {
  __m128 x, y, z;
};

// Lane i holds field(i), for i < 4.
template <typename Field>
Lanes3 gather(const Field& field) {
  const Vec3 a = field(0), b = field(1), c = field(2), d = field(3);
  return {_mm_setr_ps(a.x, b.x, c.x, d.x), _mm_setr_ps(a.y, b.y, c.y, d.y), _mm_setr_ps(a.z, b.z, c.z, d.z)};
}

// Four rows of four floats (x, y, z, w), each at its own address, as lanes: one 16-byte load a
// row and a transpose, where gathering a coordinate at a time takes a load and an insert each.
struct Lanes4 {
  Lanes3 xyz;
  __m128 w;
};
inline Lanes4 transpose_rows(const float* a, const float* b, const float* c, const float* d) {
  __m128 r0 = _mm_loadu_ps(a), r1 = _mm_loadu_ps(b), r2 = _mm_loadu_ps(c), r3 = _mm_loadu_ps(d);
  _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
  return {{r0, r1, r2}, r3};
}

inline __m128 dot(const Lanes3& a, const Lanes3& b) {
  return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a.x, b.x), _mm_mul_ps(a.y, b.y)), _mm_mul_ps(a.z, b.z));
}

inline Lanes3 divide(const Lanes3& v, __m128 s) { return {_mm_div_ps(v.x, s), _mm_div_ps(v.y, s), _mm_div_ps(v.z, s)}; }

// c ? a : b, lane by lane (c all ones or all zeros per lane).
inline __m128 select(__m128 c, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(c, a), _mm_andnot_ps(c, b)); }
inline Lanes3 select(__m128 c, const Lanes3& a, const Lanes3& b) {
  return {select(c, a.x, b.x), select(c, a.y, b.y), select(c, a.z, b.z)};
}

// The lanes' x, y and z into three arrays of four.
inline void store(const Lanes3& v, float* x, float* y, float* z) {
  _mm_storeu_ps(x, v.x);
  _mm_storeu_ps(y, v.y);
  _mm_storeu_ps(z, v.z);
}

}  // namespace rtpro::lanes
