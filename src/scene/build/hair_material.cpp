#include "rtpro/scene/hair_material.h"

#include "rtpro/scene/hair_absorption.h"

namespace rtpro {

namespace {

Color sigma_a_of(const HairParams& params) {
  switch (params.absorption) {
    case HairAbsorption::kSigmaA: return params.sigma_a;
    case HairAbsorption::kMelanin: return hair_sigma_a_from_melanin(params.eumelanin, params.pheomelanin);
    case HairAbsorption::kColor:
    case HairAbsorption::kUnset: break;
  }
  return Color(0.0f);
}

}  // namespace

HairSurface surface_model_from(const HairParams& params, const MaterialDesc&, std::vector<TextureImage>&) {
  const Color sigma_a = sigma_a_of(params);
  return {params.beta_m,
          params.beta_n,
          params.alpha_degrees,
          params.ior,
          params.absorption == HairAbsorption::kColor,
          sigma_a,
          hair_color_from_sigma_a(sigma_a, params.beta_n)};
}

WhittedMaterial whitted_approximation_of(const HairParams& params, const MaterialDesc&, const ColorTexture& color) {
  const float r0 = (params.ior - 1.0f) / (params.ior + 1.0f);
  const ColorTexture diffuse = params.absorption == HairAbsorption::kColor
                                   ? color
                                   : ColorTexture(hair_color_from_sigma_a(sigma_a_of(params), params.beta_n));
  return {diffuse, r0 * r0, phong_exponent_of_roughness(params.beta_m), 0.0f, std::nullopt};
}

}  // namespace rtpro
