#pragma once
// Small fixtures several test files share.
#include "rtpro/core/error.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/image/image.h"

#include <xmmintrin.h>

#include <filesystem>

namespace rtpro::test {

// An RGB image whose every pixel and channel differs: 0.1·x + 0.01·y + 0.3·c.
Image gradient_image(int width, int height);

// The InputError load_mesh_file throws for `file`; records a test failure if none is thrown.
InputError mesh_load_error(const std::filesystem::path& file);

// Reads both image files and records a test failure unless their channels and every float of
// their pixels are the same, bit for bit.
void expect_same_pixels(const std::filesystem::path& reference, const std::filesystem::path& test);

// Records a test failure unless `actual` has `expected`'s size and each of its channels, found by
// name (EXR stores channels sorted by name), with the same floats, bit for bit.
void expect_same_channels(const Image& expected, const Image& actual);

// Runs `check` in the floating-point mode of tracing threads (set_tracing_fp_mode: denormals flush
// to zero), then restores this thread's own mode.
template <typename Check>
void in_tracing_fp_mode(Check&& check) {
  const unsigned saved = _mm_getcsr();
  set_tracing_fp_mode();
  check();
  _mm_setcsr(saved);
}

}  // namespace rtpro::test
