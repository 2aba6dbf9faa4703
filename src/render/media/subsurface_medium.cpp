#include "subsurface_medium.h"

#include "rtpro/core/math_constants.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

constexpr float kMinAlbedo = 0.2f;
// Below it a channel's walk would have a mean free path no float distance resolves.
constexpr float kMinPath = 1e-16f;

// Horner's rule for c[0] + c[1] g + … + c[7] g⁷.
float polynomial7(const float (&c)[8], float g) {
  float sum = c[7];
  for (int i = 6; i >= 0; --i) sum = sum * g + c[i];
  return sum;
}

// F_dr, the hemispherical average of a dielectric boundary's Fresnel reflectance seen from inside
// (Egan and Hilgeman's fit), made into the dipole's boundary term.
float dipole_boundary(float ior) {
  const float eta = std::clamp(ior, 1.01f, 3.8f);
  const float inv_eta = 1.0f / eta;
  const float fdr = inv_eta * (-1.440f * inv_eta + 0.710f) + 0.668f + 0.0636f * eta;
  return (4.0f / 3.0f) * (1.0f + fdr) / (1.0f - fdr);
}

}  // namespace

float single_scattering_albedo(float surface_albedo, float g) {
  // The fit's six coefficient functions of g (Wrenninge et al. 2017, table 1): the albedo is a
  // blend, by A^¼, of two curves a·atan(b A)^c.
  static constexpr float kA[8] = {1.8260523782f,   -1.28451056436f, -1.79904629312f, 9.19393289202f,
                                  -22.8215585862f, 32.0234874259f,  -23.6264803333f, 7.21067002658f};
  static constexpr float kB[8] = {0.0f,           31.1491581433f,  -201.847017512f, 841.576016723f, -2018.09288505f,
                                  2731.71560286f, -1935.41424244f, 559.009054474f};
  static constexpr float kC[8] = {1.09686102424f, -0.394704063468f, 1.05258115941f, -8.83963712726f,
                                  28.8643230661f, -46.8802913581f,  38.5402837518f, -12.7181042538f};
  static constexpr float kD[8] = {0.496310210422f, 0.360146581622f, -2.15139309747f, 17.8896899217f,
                                  -55.2984010333f, 82.065982243f,   -58.5106008578f, 15.8478295021f};
  static constexpr float kE[8] = {0.0f,           76.7316253952f,  -594.356773233f, 2448.8834203f, -5576.68528998f,
                                  7116.60171912f, -4763.54467887f, 1303.5318055f};
  static constexpr float kF[8] = {2.40602999408f, -2.51814844609f, 9.18494908356f, -79.2191708682f,
                                  259.082868209f, -403.613804597f, 302.85712436f,  -87.4370473567f};
  const float a = polynomial7(kA, g);
  const float b = 4.98511194385f + 0.127355959438f * std::exp(polynomial7(kB, g));
  const float c = polynomial7(kC, g);
  const float d = polynomial7(kD, g);
  const float e = 4.23190299701f + 0.00310603949088f * std::exp(polynomial7(kE, g));
  const float f = polynomial7(kF, g);
  const float blend = std::pow(surface_albedo, 0.25f);
  const float albedo = (1.0f - blend) * a * std::pow(std::atan(b * surface_albedo), c) +
                       blend * d * std::pow(std::atan(e * surface_albedo), f);
  return std::clamp(albedo, 0.0f, 0.999999f);  // 1 would be a walk that never ends
}

float dipole_reflectance(float reduced_albedo, float boundary) {
  const float s = std::sqrt(3.0f * (1.0f - reduced_albedo));
  return 0.5f * reduced_albedo * (1.0f + std::exp(-boundary * s)) * std::exp(-s);
}

float dipole_reduced_albedo(float reflectance, float boundary) {
  if (reflectance < 1e-4f) return 0.0f;
  if (reflectance >= 0.995f) return 0.999999f;
  float low = 0.0f, high = 1.0f, middle = 0.5f;
  for (int i = 0; i < 12; ++i) {  // 2⁻¹² of α': below what any albedo texture resolves
    middle = 0.5f * (low + high);
    (dipole_reflectance(middle, boundary) < reflectance ? low : high) = middle;
  }
  return middle;
}

SubsurfaceMedium subsurface_medium(const Color& surface_albedo, const Color& radius, float anisotropy, float ior,
                                   SubsurfaceMethod method) {
  const float g = std::clamp(anisotropy, 0.0f, 0.9f);
  const float boundary = dipole_boundary(ior);
  SubsurfaceMedium medium{Color(0.0f), Color(0.0f), g, Color(1.0f)};
  for (int c = 0; c < 3; ++c) {
    const float albedo = std::clamp(surface_albedo[c], 0.0f, 1.0f);
    float path = radius[c];
    switch (method) {
      case SubsurfaceMethod::kRandomWalk:
        path *= std::sqrt(3.0f * (1.0f - dipole_reduced_albedo(albedo, boundary)));
        break;
      case SubsurfaceMethod::kRandomWalkFixedRadius: path *= 0.25f * kInvPi; break;
    }
    medium.sigma_t[c] = 1.0f / (std::max(path, kMinPath) * (1.0f - g));
    medium.albedo[c] = single_scattering_albedo(albedo, g);
    if (medium.albedo[c] < kMinAlbedo) {
      medium.weight[c] = medium.albedo[c] / kMinAlbedo;
      medium.albedo[c] = kMinAlbedo;
    }
  }
  return medium;
}

const SubsurfaceMedium& SubsurfaceMediumCache::get(const Color& surface_albedo, const Color& radius, float anisotropy,
                                                   float ior, SubsurfaceMethod method) {
  const Inputs inputs{surface_albedo, radius, anisotropy, ior, method};
  if (inputs_ != inputs) {  // NaN inputs never match: made again, as without the cache
    medium_ = subsurface_medium(surface_albedo, radius, anisotropy, ior, method);
    inputs_ = inputs;
  }
  return medium_;
}

}  // namespace rtpro
