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

// Each kind's BSDF and the albedo its AOV shows, written into `out` (the frame is left to the
// caller), evaluating only the colour textures it reads; returns the shading normal, on the side
// the ray came from. Written in place: a record returned and then moved into the caller's was
// copied with wide loads over the narrow stores that built it, a store-forwarding stall per vertex.
struct ToBsdf {
  const Material& material;
  const SurfacePoint& point;
  const TextureLookup* textures;
  SurfaceBsdf& out;

  Color color() const { return evaluate(material.color, point, textures); }
  Vec3 diffuse(const Color& reflectance, const Vec3& normal) const {
    out.bsdf = DiffuseBsdf{reflectance};
    out.albedo = reflectance;
    return normal;
  }

  Vec3 operator()(const PhongSurface&) const {
    const Color c = color();
    if (!material.dielectric) return diffuse(c, point.shading_normal);
    out.bsdf = DielectricBsdf{material.dielectric->ior, 0.0f};
    out.albedo = c;
    return point.shading_normal;
  }
  Vec3 operator()(const DiffuseSurface&) const { return diffuse(color(), point.shading_normal); }
  Vec3 operator()(const ConductorSurface& conductor) const {
    const float alpha = roughness_to_alpha(conductor.roughness);
    const Color c = color();
    out.bsdf = conductor.has_complex_ior ? ConductorBsdf::from_complex_ior(conductor.eta, conductor.k, alpha)
                                         : ConductorBsdf::from_f0(c, alpha);
    out.albedo = c;
    return point.shading_normal;
  }
  Vec3 operator()(const DielectricSurface& d) const {
    out.bsdf = DielectricBsdf{material.dielectric ? material.dielectric->ior : 1.5f, roughness_to_alpha(d.roughness)};
    out.albedo = color();
    return point.shading_normal;
  }
  // Material::color is the Whitted view's; the model's base colour is its own texture.
  Vec3 operator()(const PrincipledSurface& p) const {
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
      return diffuse(parameters.base_color, normal);
    out.bsdf = PrincipledBsdf(parameters);
    out.albedo = parameters.base_color;
    return normal;
  }
};

}  // namespace

void material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures,
                   SurfaceBsdf& out) {
  const Vec3 normal = std::visit(ToBsdf{material, point, textures, out}, material.model);
  // Whether the BSDF tells the inside from the outside (it transmits): then its frame's +z is the
  // outside rather than the side the ray came from.
  const bool outward = std::visit([](const auto& b) { return b.needs_outward_frame(); }, out.bsdf);
  out.frame = ShadingFrame::from_normal(!outward || point.front_face ? normal : -normal);
}

}  // namespace rtpro
