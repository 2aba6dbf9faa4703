#include "rtpro/scene/principled_material.h"

#include "material_textures.h"
#include "mtl_parser.h"  // kFullHighlightNs

#include "rtpro/core/overloaded.h"

#include <algorithm>
#include <variant>

namespace rtpro {

PrincipledSurface surface_model_from(const PrincipledParams& p, const MaterialDesc&,
                                     std::vector<TextureImage>& textures) {
  PrincipledSurface surface{p.metalness,
                            p.roughness,
                            p.ior,
                            p.specular_weight,
                            p.specular_color,
                            p.transmission_weight,
                            p.coat_weight,
                            p.coat_roughness,
                            p.fuzz_color,
                            p.fuzz_roughness,
                            p.subsurface,
                            p.subsurface_radius * p.subsurface_scale,
                            p.subsurface_anisotropy,
                            p.subsurface_method,
                            std::nullopt,
                            std::nullopt};
  surface.metallic_roughness =
      slot_texture(p.metallic_roughness_texture, Color(1.0f, p.roughness, p.metalness), textures);
  if (const std::optional<ImageTexture> normals = slot_texture(p.normal_texture, Color(1.0f), textures))
    surface.normal_map = NormalMap{normals->image, p.normal_scale, normals->sampling};
  return surface;
}

namespace {

// `color` with its tint times `factor`: a constant's value, an image's tint. A checkerboard's
// squares are the scene file's colours, which no tint multiplies, and stay as they are.
ColorTexture with_tint_scaled(const ColorTexture& color, float factor) {
  return std::visit(Overloaded{[&](const Color& c) -> ColorTexture { return c * factor; },
                               [](const CheckerTexture& checker) -> ColorTexture { return checker; },
                               [&](ImageTexture image) -> ColorTexture {
                                 image.tint = image.tint * factor;
                                 return image;
                               }},
                    color);
}

}  // namespace

// With F0 = 0.04 + (mean(base) − 0.04) × metallic and gloss = (1 − roughness)², the mirror takes
// F0 × gloss and the diffuse colour what the mirror leaves; the highlight is the peak of an
// energy-normalised Phong lobe about as wide as the GGX one.
WhittedMaterial whitted_approximation_of(const PrincipledParams& p, const MaterialDesc& material,
                                         const ColorTexture& color) {
  const Color base = material.color;
  const float metallic = p.metalness, roughness = p.roughness;
  const float f0 = 0.04f + ((base.x + base.y + base.z) / 3.0f - 0.04f) * metallic;
  const float gloss = (1.0f - roughness) * (1.0f - roughness);
  const float alpha4 = std::max(roughness * roughness * roughness * roughness, 1e-6f);
  const float n = std::clamp(2.0f / alpha4 - 2.0f, 1.0f, 10000.0f);
  const float reflectivity = std::clamp(f0 * gloss, 0.0f, 1.0f);
  const float specular = std::min(f0 * (n + 2.0f) / 2.0f, 2.0f) * std::min(1.0f, n / kFullHighlightNs);
  return {with_tint_scaled(color, 1.0f - reflectivity), specular, n, reflectivity, std::nullopt};
}

}  // namespace rtpro
