#include "phong_bsdf.h"

#include "material_bsdf.h"
#include "texture.h"

namespace rtpro {

Vec3 bsdf_from(const PhongSurface&, const Material& material, const SurfacePoint& point, const TextureLookup* textures,
               SurfaceBsdf& out) {
  const Color c = evaluate(material.color, point, textures);
  if (!material.dielectric) return lambert_surface(c, point.shading_normal, out);
  out.bsdf = DielectricBsdf{material.dielectric->ior, 0.0f};
  out.albedo = c;
  return point.shading_normal;
}

}  // namespace rtpro
