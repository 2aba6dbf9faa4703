#include "rtpro/render/material_bsdf.h"

#include "rtpro/render/microfacet.h"
#include "rtpro/render/texture.h"

#include <variant>

namespace rtpro {

namespace {

// Each kind's BSDF and the albedo its AOV shows, evaluating only the colour textures it reads.
struct ToBsdf {
  const Material& material;
  const SurfacePoint& point;
  const TextureLookup* textures;

  struct Result {
    Bsdf bsdf;
    Color albedo;
  };
  Color color() const { return evaluate(material.color, point, textures); }

  Result operator()(const PhongSurface&) const {
    const Color c = color();
    if (material.dielectric) return {DielectricBsdf{material.dielectric->ior, 0.0f}, c};
    return {DiffuseBsdf{c}, c};
  }
  Result operator()(const DiffuseSurface&) const {
    const Color c = color();
    return {DiffuseBsdf{c}, c};
  }
  Result operator()(const ConductorSurface& conductor) const {
    const float alpha = roughness_to_alpha(conductor.roughness);
    const Color c = color();
    if (conductor.has_complex_ior) return {ConductorBsdf::from_complex_ior(conductor.eta, conductor.k, alpha), c};
    return {ConductorBsdf::from_f0(c, alpha), c};
  }
  Result operator()(const DielectricSurface& d) const {
    return {DielectricBsdf{material.dielectric ? material.dielectric->ior : 1.5f, roughness_to_alpha(d.roughness)},
            color()};
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
    // KHR_materials_specular's specularFactor 0 on a non-metal without other layers is the pure
    // Lambert base, by the extension's definition: the same f and pdf from the cheaper kind.
    if (p.specular_weight == 0.0f && p.metalness == 0.0f && p.transmission_weight == 0.0f && p.coat_weight == 0.0f &&
        max_component(p.fuzz_color) == 0.0f)
      return {DiffuseBsdf{parameters.base_color}, parameters.base_color};
    return {PrincipledBsdf(parameters), parameters.base_color};
  }
};

// Whether the BSDF tells the inside from the outside (it transmits): then its frame's +z is the
// outside rather than the side the ray came from.
struct NeedsOutwardFrame {
  bool operator()(const DiffuseBsdf&) const { return false; }
  bool operator()(const ConductorBsdf&) const { return false; }
  bool operator()(const DielectricBsdf&) const { return true; }
  bool operator()(const PrincipledBsdf& p) const { return p.needs_outward_frame(); }
};

}  // namespace

SurfaceBsdf material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures) {
  ToBsdf::Result made = std::visit(ToBsdf{material, point, textures}, material.model);
  const bool outward = std::visit(NeedsOutwardFrame{}, made.bsdf);
  const Vec3 normal = !outward || point.front_face ? point.shading_normal : -point.shading_normal;
  return {std::move(made.bsdf), ShadingFrame::from_normal(normal), made.albedo};
}

}  // namespace rtpro
