#include "rtpro/render/material_bsdf.h"

#include "rtpro/render/microfacet.h"
#include "rtpro/render/texture.h"

#include <cmath>
#include <variant>

namespace rtpro {

namespace {

// The normal a normal map gives at `point`, on the side the ray came from; the shading normal
// where the map or the surface's frame says nothing usable (a degenerate tangent, a mapped normal
// facing away from the ray).
Vec3 mapped_normal(const NormalMap& map, const SurfacePoint& point, const TextureLookup* textures) {
  const Vec3 n = point.shading_normal;
  const Vec3 tangent = point.tangent - n * dot(n, point.tangent);
  const float tangent_length = length(tangent);
  if (!(tangent_length > 0.0f) || !std::isfinite(tangent_length)) return n;
  const Vec3 t = tangent / tangent_length;
  // The map is defined on the outside, where the bitangent is outside normal × tangent; seen from
  // the inside the normal is flipped, and with it the cross product.
  const float side = point.front_face ? 1.0f : -1.0f;
  const Vec3 b = cross(n, t) * point.bitangent_sign;
  const Color texel =
      evaluate(ImageTexture{map.image, Color(1.0f), TextureWrap::kRepeat}, point.tex_u, point.tex_v, textures);
  const float x = (2.0f * texel.x - 1.0f) * map.scale, y = (2.0f * texel.y - 1.0f) * map.scale;
  const float z = 2.0f * texel.z - 1.0f;
  const Vec3 mapped = t * (side * x) + b * y + n * z;
  const float mapped_length = length(mapped);
  if (!(mapped_length > 0.0f) || !std::isfinite(mapped_length)) return n;
  const Vec3 unit = mapped / mapped_length;
  return dot(unit, point.geometric_normal) > 0.0f ? unit : n;
}

// Each kind's BSDF and the albedo its AOV shows, evaluating only the colour textures it reads.
struct ToBsdf {
  const Material& material;
  const SurfacePoint& point;
  const TextureLookup* textures;

  struct Result {
    Bsdf bsdf;
    Color albedo;
    Vec3 normal;  // the shading normal, on the side the ray came from
  };
  Color color() const { return evaluate(material.color, point, textures); }

  Result operator()(const PhongSurface&) const {
    const Color c = color();
    if (material.dielectric) return {DielectricBsdf{material.dielectric->ior, 0.0f}, c, point.shading_normal};
    return {DiffuseBsdf{c}, c, point.shading_normal};
  }
  Result operator()(const DiffuseSurface&) const {
    const Color c = color();
    return {DiffuseBsdf{c}, c, point.shading_normal};
  }
  Result operator()(const ConductorSurface& conductor) const {
    const float alpha = roughness_to_alpha(conductor.roughness);
    const Color c = color();
    if (conductor.has_complex_ior)
      return {ConductorBsdf::from_complex_ior(conductor.eta, conductor.k, alpha), c, point.shading_normal};
    return {ConductorBsdf::from_f0(c, alpha), c, point.shading_normal};
  }
  Result operator()(const DielectricSurface& d) const {
    return {DielectricBsdf{material.dielectric ? material.dielectric->ior : 1.5f, roughness_to_alpha(d.roughness)},
            color(), point.shading_normal};
  }
  // Material::color is the Whitted view's; the model's base colour is its own texture.
  Result operator()(const PrincipledSurface& p) const {
    PrincipledParameters parameters;
    parameters.base_color = evaluate(p.base_color, point, textures);
    parameters.metalness = p.metalness;
    parameters.roughness = p.roughness;
    parameters.ior = p.ior;
    parameters.specular_weight = p.specular_weight;
    parameters.specular_color = p.specular_color;
    parameters.transmission_weight = p.transmission_weight;
    parameters.coat_weight = p.coat_weight;
    parameters.coat_roughness = p.coat_roughness;
    parameters.fuzz_color = p.fuzz_color;
    parameters.fuzz_roughness = p.fuzz_roughness;
    if (p.metallic_roughness) {
      const Color texel = evaluate(*p.metallic_roughness, point.tex_u, point.tex_v, textures);
      parameters.roughness = texel.y;
      parameters.metalness = texel.z;
    }
    const Vec3 normal = p.normal_map ? mapped_normal(*p.normal_map, point, textures) : point.shading_normal;
    // KHR_materials_specular's specularFactor 0 on a non-metal without other layers is the pure
    // Lambert base, by the extension's definition: the same f and pdf from the cheaper kind.
    if (p.specular_weight == 0.0f && parameters.metalness == 0.0f && p.transmission_weight == 0.0f &&
        p.coat_weight == 0.0f && max_component(p.fuzz_color) == 0.0f)
      return {DiffuseBsdf{parameters.base_color}, parameters.base_color, normal};
    return {PrincipledBsdf(parameters), parameters.base_color, normal};
  }
};

}  // namespace

SurfaceBsdf material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures) {
  ToBsdf::Result made = std::visit(ToBsdf{material, point, textures}, material.model);
  // Whether the BSDF tells the inside from the outside (it transmits): then its frame's +z is the
  // outside rather than the side the ray came from.
  const bool outward = std::visit([](const auto& b) { return b.needs_outward_frame(); }, made.bsdf);
  const Vec3 normal = !outward || point.front_face ? made.normal : -made.normal;
  return {std::move(made.bsdf), ShadingFrame::from_normal(normal), made.albedo};
}

}  // namespace rtpro
