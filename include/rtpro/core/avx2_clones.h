#pragma once
// RTPRO_AVX2_CLONES before a hot function compiles it twice, for AVX2 and for the baseline x86-64
// the project targets, and the dynamic loader picks one at start-up (function multiversioning: an
// ifunc, resolved once). The AVX2 version is the same arithmetic in VEX three-operand encodings,
// without most of the register copies SSE2 needs: the shading kernels ran 1-3% faster. Both
// versions compute the same bits: floating-point contraction is off project-wide, AVX2 does not
// imply FMA, no -ffast-math lets the vectoriser reorder float operations, and each IEEE operation
// rounds the same in either encoding. A CPU without AVX2 runs the baseline version, as before.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RTPRO_AVX2_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define RTPRO_AVX2_CLONES
#endif
