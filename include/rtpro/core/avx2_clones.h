#pragma once
// RTPRO_AVX2_CLONES before a hot function compiles it twice, for AVX2 and for the baseline x86-64
// the project targets, and the dynamic loader picks one at start-up (function multiversioning: an
// ifunc, resolved once). The AVX2 version is the same arithmetic in VEX three-operand encodings,
// without most of the register copies SSE2 needs: a render with the shading kernels cloned ran
// 1-3% faster, and with the camera samples and Embree's packet loops and sphere callbacks cloned
// too, many_spheres on Embree a further 6.7% (9 interleaved runs). Both
// versions compute the same bits: floating-point contraction is off project-wide, AVX2 does not
// imply FMA, no -ffast-math lets the vectoriser reorder float operations, and each IEEE operation
// rounds the same in either encoding. A CPU without AVX2 runs the baseline version, as before.
//
// Clang 14 calls a multiversioned function through a dispatcher of its own file: put the macro on
// free functions, or on members called only in their own file, and define them before their first
// call there (a member function called from another file does not link).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define RTPRO_AVX2_CLONES [[gnu::target_clones("avx2", "default")]]
#else
#define RTPRO_AVX2_CLONES
#endif
