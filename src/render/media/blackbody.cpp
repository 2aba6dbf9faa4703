#include "blackbody.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rtpro {

namespace {

constexpr float kMinKelvin = 800.0f, kMaxKelvin = 12000.0f;
constexpr int kTableSize = 1024;

// The CIE 1931 colour matching functions by the multi-lobe Gaussian fit of Wyman, Sloan and
// Shirley 2013 (JCGT 2(2)): within a few percent of the tabulated functions, which is far below
// what a temperature grid's own uncertainty moves a flame's colour.
double lobe(double lambda, double mu, double below, double above) {
  const double t = (lambda - mu) / (lambda < mu ? below : above);
  return std::exp(-0.5 * t * t);
}

Color planck_rec709(double kelvin) {
  constexpr double kC2 = 1.4387769e7;  // second radiation constant, nm·K
  double x = 0.0, y = 0.0, z = 0.0;
  for (double lambda = 360.0; lambda <= 830.0; lambda += 1.0) {
    const double radiance = 1.0 / (std::pow(lambda, 5.0) * std::expm1(kC2 / (lambda * kelvin)));
    x += radiance * (1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7) -
                     0.065 * lobe(lambda, 501.1, 20.4, 26.2));
    y += radiance * (0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1));
    z += radiance * (1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8));
  }
  x /= y;
  z /= y;
  // XYZ to linear Rec.709 (D65), for Y = 1.
  return Color{static_cast<float>(3.2404542 * x - 1.5371385 - 0.4985314 * z),
               static_cast<float>(-0.9692660 * x + 1.8760108 + 0.0415560 * z),
               static_cast<float>(0.0556434 * x - 0.2040259 + 1.0572252 * z)};
}

// Evenly spaced in kelvin over [kMinKelvin, kMaxKelvin], filled once.
const std::array<Color, kTableSize>& colour_table() {
  static const std::array<Color, kTableSize> table = [] {
    std::array<Color, kTableSize> t{};
    for (int i = 0; i < kTableSize; ++i)
      t[i] = planck_rec709(kMinKelvin + (kMaxKelvin - kMinKelvin) * i / double(kTableSize - 1));
    return t;
  }();
  return table;
}

}  // namespace

Color blackbody_color(float kelvin) {
  const float clamped = std::clamp(std::isnan(kelvin) ? kMinKelvin : kelvin, kMinKelvin, kMaxKelvin);
  const float at = (clamped - kMinKelvin) / (kMaxKelvin - kMinKelvin) * (kTableSize - 1);
  const int i = std::min(static_cast<int>(at), kTableSize - 2);
  const float f = at - static_cast<float>(i);
  const std::array<Color, kTableSize>& table = colour_table();
  return table[i] * (1.0f - f) + table[i + 1] * f;
}

Color blackbody_emission(float kelvin) {
  if (!(kelvin > 0.0f)) return Color(0.0f);
  constexpr double kStefanBoltzmann = 5.670374419e-8;  // W m⁻² K⁻⁴
  constexpr double kPi = 3.14159265358979323846;
  const double t2 = double(kelvin) * double(kelvin);
  const float radiance = static_cast<float>(kStefanBoltzmann * 1e-6 / kPi * t2 * t2);
  return max(blackbody_color(kelvin), Color(0.0f)) * radiance;
}

}  // namespace rtpro
