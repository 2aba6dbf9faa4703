#include "rtpro/scene/dielectric_material.h"

namespace rtpro {

DielectricSurface surface_model_from(const DielectricParams& params, const MaterialDesc&, std::vector<TextureImage>&) {
  return {params.roughness};
}

WhittedFields whitted_approximation_of(const DielectricParams& params, const MaterialDesc&) {
  return {1.0f - params.roughness, phong_exponent_of_roughness(params.roughness), 0.0f, params.glass};
}

}  // namespace rtpro
