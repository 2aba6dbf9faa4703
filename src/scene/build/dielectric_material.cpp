#include "rtpro/scene/dielectric_material.h"

namespace rtpro {

DielectricSurface surface_model_from(const DielectricParams& params, const MaterialDesc&, std::vector<TextureImage>&) {
  return {params.roughness, params.glass};
}

WhittedMaterial whitted_approximation_of(const DielectricParams& params, const MaterialDesc&,
                                         const ColorTexture& color) {
  return {color, 1.0f - params.roughness, phong_exponent_of_roughness(params.roughness), 0.0f, params.glass};
}

}  // namespace rtpro
