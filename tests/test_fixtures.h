#pragma once
// Small fixtures several test files share.
#include "rtpro/core/error.h"
#include "rtpro/core/fp_env.h"
#include "rtpro/image/image.h"

#include <gtest/gtest.h>
#include <xmmintrin.h>

#include <filesystem>
#include <string>

namespace rtpro::test {

// The sum of every value of every pixel of `image`: positive for a render that is not black.
double image_sum(const Image& image);

// The scene text of a white furnace: a sphere of radius 1 of `material` (a YAML flow map) filling
// a `size`×`size` image under a uniform background of radiance 1, path traced at `spp` with
// max_depth 64. A material that neither creates nor loses light vanishes in it.
std::string white_furnace_scene(const std::string& material, int size, int spp);

// The OBJ text of an n × n grid of squares `spacing` apart, two triangles each, whose height at
// grid point (x, y) is amplitude · sin(fx · x) · cos(fy · y): smooth normals on it point every
// which way.
std::string bumpy_grid_obj(int n, double spacing, double amplitude, double fx, double fy);

// An RGB image whose every value is `value`.
Image uniform_image(int width, int height, float value);

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

// The what() of the `Error` that `action` throws; records a test failure when it throws none.
template <typename Error, typename Action>
std::string error_message_of(Action&& action) {
  try {
    action();
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "the expected error was not thrown";
  return {};
}

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
