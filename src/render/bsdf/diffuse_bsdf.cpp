#include "diffuse_bsdf.h"

#include "rtpro/scene/diffuse_material.h"
#include "surface_bsdf.h"
#include "texture.h"

#include <numbers>

namespace rtpro {

float DiffuseBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!same_hemisphere(wo, wi)) return 0.0f;
  return cosine_hemisphere_pdf(abs_cos_theta(wi));
}

Vec3 bsdf_from(const DiffuseSurface&, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  return lambert_surface(evaluate(base_color, point, textures), point.shading_normal, out);
}

}  // namespace rtpro
