#pragma once
// The denoiser's regression works on rows of kLanes pixels at once: the tile it fills, the vector
// type holding one value of kLanes pixels, and the arithmetic on it that must stay inlined.
#include <bit>
#include <cstdint>
#include <cstring>

namespace rtpro::regression {

// Output tiles: the unit of parallel work, and of the per-offset weight images (a tile's weights
// for every offset are computed before its regressions, so patch distances are summed once).
constexpr int kTileSize = 32;
// Pixels of a row handled together by the regression's sums: one AVX register of floats. Clang
// refuses 256-bit vectors across its inlined helpers in the baseline clone (an ABI error, not a
// note), so a Clang build (the sanitizer tree) takes SSE widths; each lane is its own pixel, so
// the results are the same bits at either width.
#if defined(__clang__)
constexpr int kLanes = 4;
#else
constexpr int kLanes = 8;
#endif
constexpr int kGroups = kTileSize / kLanes;
// Distances above this give weights of e^-80 and below: none.
constexpr float kDistanceClamp = 80.0f;

// kLanes floats as one value (GCC's vector extension: AVX registers in the AVX2 clone, pairs of
// SSE registers in the baseline one; the same IEEE operations either way). Every helper on them
// is inlined into its caller, so no vector crosses a call (GCC's -Wpsabi note is about calls; it
// is given for the file's end, where the templates are instantiated, so it stays off to there).
#pragma GCC diagnostic ignored "-Wpsabi"
using Lanes = float __attribute__((vector_size(kLanes * sizeof(float))));
using IntLanes = std::int32_t __attribute__((vector_size(kLanes * sizeof(std::int32_t))));

[[gnu::always_inline]] inline Lanes load_lanes(const float* p) {
  Lanes v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
[[gnu::always_inline]] inline void store_lanes(float* p, Lanes v) { std::memcpy(p, &v, sizeof v); }

// How many kLanes-wide chunks cover `count` values.
int lane_chunks(int count) { return (count + kLanes - 1) / kLanes; }

// NaN (from absurd inputs) becomes the clamp too: the comparison is false for it.
[[gnu::always_inline]] inline Lanes clamped_distance(Lanes d) {
  return d < kDistanceClamp ? d : Lanes{} + kDistanceClamp;
}

// e^-x for x >= 0 (to about 3e-6, relative), in plain arithmetic on all lanes at once (std::exp
// is a library call per value): 2^-n by the exponent bits, the rest by its Taylor series.
[[gnu::always_inline]] inline Lanes exp_negative(Lanes x) {
  const Lanes t = (x < kDistanceClamp ? x : Lanes{} + kDistanceClamp) * 1.44269504f;  // x / ln 2, <= 115.4
  const IntLanes n = __builtin_convertvector(t + 0.5f, IntLanes);
  const Lanes y = (__builtin_convertvector(n, Lanes) - t) * 0.693147181f;  // within ±ln(2)/2
  const Lanes series = 1.0f + y * (1.0f + y * (0.5f + y * (1.0f / 6.0f + y * (1.0f / 24.0f + y * (1.0f / 120.0f)))));
  return series * std::bit_cast<Lanes>((127 - n) << 23);
}

}  // namespace rtpro::regression
