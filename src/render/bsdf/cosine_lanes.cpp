#include "cosine_lanes.h"

#include "rtpro/core/lanes3.h"
#include "rtpro/core/avx2_clones.h"

#include <emmintrin.h>

#include <numbers>

namespace rtpro {

namespace {

template <class T>
T& at(T* first, std::size_t i, std::size_t stride) {
  using Byte = std::conditional_t<std::is_const_v<T>, const std::byte, std::byte>;
  return *reinterpret_cast<T*>(reinterpret_cast<Byte*>(first) + i * stride);
}

__m128 abs4(__m128 v) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), v); }

}  // namespace

RTPRO_AVX2_CLONES
void sample_cosine_hemispheres(std::size_t count, const Sample2D* u, Vec3* out, std::size_t stride) {
  using lanes::select;
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const Sample2D& a = at(u, i, stride);
    const Sample2D& b = at(u, i + 1, stride);
    const Sample2D& c = at(u, i + 2, stride);
    const Sample2D& d = at(u, i + 3, stride);
    const __m128 two = _mm_set1_ps(2.0f), one = _mm_set1_ps(1.0f), zero = _mm_setzero_ps();
    // sample_uniform_disk_concentric: x and y in [-1, 1).
    const __m128 x = _mm_sub_ps(_mm_mul_ps(two, _mm_setr_ps(a.x, b.x, c.x, d.x)), one);
    const __m128 y = _mm_sub_ps(_mm_mul_ps(two, _mm_setr_ps(a.y, b.y, c.y, d.y)), one);
    const __m128 centre = _mm_and_ps(_mm_cmpeq_ps(x, zero), _mm_cmpeq_ps(y, zero));
    // The wedge where |x| > |y| takes φ = π/4 · y/x; the other θ = π/4 · x/y, with sine and
    // cosine swapped (φ = π/2 − θ).
    const __m128 x_wedge = _mm_cmpgt_ps(abs4(x), abs4(y));
    const __m128 ratio = _mm_div_ps(select(x_wedge, y, x), select(x_wedge, x, y));
    const __m128 angle = _mm_mul_ps(_mm_set1_ps(std::numbers::pi_v<float> / 4.0f), ratio);
    // sine_cosine_within_quarter_turn, its polynomials in their order.
    const __m128 z = _mm_mul_ps(angle, angle);
    const auto mul = _mm_mul_ps;
    const auto add = _mm_add_ps;
    const auto sub = _mm_sub_ps;
    const auto set = _mm_set1_ps;
    const __m128 sin =
        add(mul(mul(sub(mul(add(mul(set(-1.9515295891e-4f), z), set(8.3321608736e-3f)), z), set(1.6666654611e-1f)), z),
                angle),
            angle);
    const __m128 cos = add(sub(mul(mul(add(mul(sub(mul(set(2.443315711809948e-5f), z), set(1.388731625493765e-3f)), z),
                                           set(4.166664568298827e-2f)),
                                       z),
                                   z),
                               mul(set(0.5f), z)),
                           one);
    const __m128 scale = select(x_wedge, x, y);
    const __m128 disk_x = select(centre, zero, mul(scale, select(x_wedge, cos, sin)));
    const __m128 disk_y = select(centre, zero, mul(scale, select(x_wedge, sin, cos)));
    // sample_cosine_hemisphere: the height sqrt(max(0, 1 − x² − y²)); max_ps(v, 0) is v > 0 ? v : 0,
    // as std::max(0.0f, v) is, NaN and −0 included.
    const __m128 height = _mm_sqrt_ps(_mm_max_ps(sub(sub(one, mul(disk_x, disk_x)), mul(disk_y, disk_y)), zero));
    alignas(16) float ox[4], oy[4], oz[4];
    lanes::store({disk_x, disk_y, height}, ox, oy, oz);
    for (int k = 0; k < 4; ++k) at(out, i + k, stride) = {ox[k], oy[k], oz[k]};
  }
  for (; i < count; ++i) at(out, i, stride) = sample_cosine_hemisphere(at(u, i, stride));
}

}  // namespace rtpro
