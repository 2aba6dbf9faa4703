#include "rtpro/scene/conductor_material.h"

namespace rtpro {

ConductorSurface surface_model_from(const ConductorParams& params, const MaterialDesc&, std::vector<TextureImage>&) {
  return {params.roughness, params.eta.has_value(), params.eta.value_or(Color(0.0f)), params.k.value_or(Color(0.0f))};
}

WhittedMaterial whitted_approximation_of(const ConductorParams& params, const MaterialDesc&,
                                         const ColorTexture& color) {
  const float r = params.roughness;
  return {color, 1.0f - r, phong_exponent_of_roughness(r), r < 0.1f ? 1.0f - r * 10.0f : 0.0f, std::nullopt};
}

}  // namespace rtpro
