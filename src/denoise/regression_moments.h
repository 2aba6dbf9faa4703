#pragma once
// The weighted sums a pixel's regression is solved from, added kLanes pixels at a time with the
// sums kept in registers.
#include "regression_lanes.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

namespace rtpro::regression {

// The regression's sums, for D regressors x (the intercept last, x = 1) and the colour y:
// Σ w·x_a·e_b with e = (x_0 .. x_D-1, y_R, y_G, y_B). First XᵀWX's lower triangle row by row,
// then XᵀWY.
struct MomentPair {
  int a, b;
};
template <int D>
constexpr int kMoments = D*(D + 1) / 2 + 3 * D;
template <int D>
constexpr std::array<MomentPair, kMoments<D>> moment_pairs() {
  std::array<MomentPair, kMoments<D>> pairs{};
  int m = 0;
  for (int a = 0; a < D; ++a)
    for (int b = 0; b <= a; ++b) pairs[m++] = {a, b};
  for (int a = 0; a < D; ++a)
    for (int c = 0; c < 3; ++c) pairs[m++] = {a, D + c};
  return pairs;
}
inline int moment_count(int d) { return d * (d + 1) / 2 + 3 * d; }

// Sums held in registers while a window row's offsets are added: at most this many at once
// (AVX2 has 16 registers; the products need the rest).
constexpr int kBlock = 12;

// For the moments First .. First+Count-1: adds, over `offsets` staged offsets, wx[a]·e[b] to
// `sums` (moment m at sums + m·kTileSize). The pair indices are constants once unrolled, so every
// load has a fixed offset and the partial sums never leave the registers.
template <int D, int First, int Count>
[[gnu::always_inline]] inline void accumulate_block(const float* wx, const float* e, int offsets, float* sums) {
  constexpr std::array<MomentPair, kMoments<D>> pairs = moment_pairs<D>();
  Lanes acc[Count];
#pragma GCC unroll 16
  for (int k = 0; k < Count; ++k) acc[k] = Lanes{};
  for (int o = 0; o < offsets; ++o) {
    const float* wo = wx + static_cast<std::size_t>(o) * D * kLanes;
    const float* eo = e + static_cast<std::size_t>(o) * (D + 3) * kLanes;
#pragma GCC unroll 16
    for (int k = 0; k < Count; ++k)
      acc[k] += load_lanes(wo + pairs[First + k].a * kLanes) * load_lanes(eo + pairs[First + k].b * kLanes);
  }
#pragma GCC unroll 16
  for (int k = 0; k < Count; ++k) {
    float* m = sums + static_cast<std::size_t>(First + k) * kTileSize;
    store_lanes(m, load_lanes(m) + acc[k]);
  }
}

template <int D, int... Blocks>
[[gnu::always_inline]] inline void accumulate_blocks(const float* wx, const float* e, int offsets, float* sums,
                                                     std::integer_sequence<int, Blocks...>) {
  (accumulate_block<D, Blocks * kBlock, std::min(kBlock, kMoments<D> - Blocks * kBlock)>(wx, e, offsets, sums), ...);
}

template <int D>
[[gnu::always_inline]] inline void accumulate_moments(const float* wx, const float* e, int offsets, float* sums) {
  accumulate_blocks<D>(wx, e, offsets, sums, std::make_integer_sequence<int, (kMoments<D> + kBlock - 1) / kBlock>{});
}

// The same for a regressor count known only at run time: screen x and y and the intercept, after
// the normal (3) and the inverse depth (1) when present.
[[gnu::always_inline]] inline void accumulate_moments(int d, const float* wx, const float* e, int offsets,
                                                      float* sums) {
  switch (d) {
    case 3: return accumulate_moments<3>(wx, e, offsets, sums);
    case 4: return accumulate_moments<4>(wx, e, offsets, sums);
    case 6: return accumulate_moments<6>(wx, e, offsets, sums);
    case 7: return accumulate_moments<7>(wx, e, offsets, sums);
  }
}

}  // namespace rtpro::regression
