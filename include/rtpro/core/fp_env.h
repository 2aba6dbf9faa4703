#pragma once
// The floating-point environment every tracing thread runs in. Embree asks for flush-to-zero and
// denormals-are-zero on each thread that calls it (denormals are very slow in its kernels), and the
// native backend must see the same mode, or the two backends could round the same sphere
// intersection differently. The renderer and the cross-checker call this once per worker thread.
namespace rtpro {

// Sets flush-to-zero and denormals-are-zero for the calling thread (SSE control register).
void set_tracing_fp_mode();

}  // namespace rtpro
