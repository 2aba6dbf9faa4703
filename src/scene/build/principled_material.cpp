#include "rtpro/scene/principled_material.h"

#include "material_textures.h"
#include "mtl_parser.h"  // kFullHighlightNs

#include <algorithm>

namespace rtpro {

PrincipledSurface surface_model_from(const PrincipledParams& p, const MaterialDesc& material,
                                     std::vector<TextureImage>& textures) {
  PrincipledSurface surface{color_texture(material, material.color, textures),
                            p.metalness,
                            p.roughness,
                            p.ior,
                            p.specular_weight,
                            p.specular_color,
                            p.transmission_weight,
                            p.coat_weight,
                            p.coat_roughness,
                            p.fuzz_color,
                            p.fuzz_roughness,
                            std::nullopt,
                            std::nullopt};
  surface.metallic_roughness =
      slot_texture(p.metallic_roughness_texture, Color(1.0f, p.roughness, p.metalness), textures);
  if (const std::optional<ImageTexture> normals = slot_texture(p.normal_texture, Color(1.0f), textures))
    surface.normal_map = NormalMap{normals->image, p.normal_scale};
  return surface;
}

// With F0 = 0.04 + (mean(base) − 0.04) × metallic and gloss = (1 − roughness)², the mirror takes
// F0 × gloss and the diffuse colour what the mirror leaves; the highlight is the peak of an
// energy-normalised Phong lobe about as wide as the GGX one.
WhittedFields whitted_approximation_of(const PrincipledParams& p, const MaterialDesc& material) {
  const Color base = material.color;
  const float metallic = p.metalness, roughness = p.roughness;
  const float f0 = 0.04f + ((base.x + base.y + base.z) / 3.0f - 0.04f) * metallic;
  const float gloss = (1.0f - roughness) * (1.0f - roughness);
  const float alpha4 = std::max(roughness * roughness * roughness * roughness, 1e-6f);
  const float n = std::clamp(2.0f / alpha4 - 2.0f, 1.0f, 10000.0f);
  WhittedFields whitted;
  whitted.reflectivity = std::clamp(f0 * gloss, 0.0f, 1.0f);
  whitted.color_scale = 1.0f - whitted.reflectivity;
  whitted.shininess = n;
  whitted.specular = std::min(f0 * (n + 2.0f) / 2.0f, 2.0f) * std::min(1.0f, n / kFullHighlightNs);
  return whitted;
}

}  // namespace rtpro
