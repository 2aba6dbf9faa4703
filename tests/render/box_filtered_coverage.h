#pragma once
// The expected value of a pixel of a motion-blurred row, for tests that integrate a shape
// crossing the frame: the fraction of the shutter a world point is covered, averaged over the
// pixel's footprint (a box filter).

namespace rtpro::test {

// Pixel x of a row `width` pixels wide, each `pixel` scene units on the plane in view, centred on
// world x = 0 with the image's x along world −x (a camera looking along +z): `covered_time(s)` is
// the fraction of the shutter during which world x = s is covered.
template <class CoveredTime>
double box_filtered_coverage(int x, int width, double pixel, CoveredTime&& covered_time) {
  constexpr int kSteps = 2000;
  const double left = -(x + 1 - width / 2) * pixel;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) sum += covered_time(left + (i + 0.5) * pixel / kSteps);
  return sum / kSteps;
}

}  // namespace rtpro::test
