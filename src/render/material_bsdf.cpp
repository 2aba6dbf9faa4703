#include "rtpro/render/material_bsdf.h"

#include "rtpro/render/microfacet.h"

#include <variant>

namespace rtpro {

namespace {

struct ToBsdf {
  const Material& material;
  const Color& color;

  Bsdf operator()(const PhongSurface&) const {
    if (material.dielectric) return DielectricBsdf{material.dielectric->ior, 0.0f};
    return DiffuseBsdf{color};
  }
  Bsdf operator()(const DiffuseSurface&) const { return DiffuseBsdf{color}; }
  Bsdf operator()(const ConductorSurface& c) const {
    const float alpha = roughness_to_alpha(c.roughness);
    return c.has_complex_ior ? ConductorBsdf::from_complex_ior(c.eta, c.k, alpha) : ConductorBsdf::from_f0(color, alpha);
  }
  Bsdf operator()(const DielectricSurface& d) const {
    return DielectricBsdf{material.dielectric ? material.dielectric->ior : 1.5f, roughness_to_alpha(d.roughness)};
  }
};

}  // namespace

SurfaceBsdf material_bsdf(const Material& material, const Color& color, const SurfacePoint& point) {
  Bsdf bsdf = std::visit(ToBsdf{material, color}, material.model);
  const bool two_sided = !std::holds_alternative<DielectricBsdf>(bsdf);
  const Vec3 normal = two_sided || point.front_face ? point.shading_normal : -point.shading_normal;
  return {std::move(bsdf), ShadingFrame::from_normal(normal)};
}

}  // namespace rtpro
