#include "phong_bsdf.h"

#include "rtpro/scene/phong_material.h"
#include "surface_bsdf.h"
#include "texture.h"

namespace rtpro {

Vec3 bsdf_from(const PhongSurface& phong, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out) {
  const Color c = evaluate(base_color, point, textures);
  if (!phong.glass) return lambert_surface(c, point.shading_normal, out);
  out.bsdf = DielectricBsdf{phong.glass->ior, 0.0f};
  out.albedo = c;
  return point.shading_normal;
}

bool makes_lambert_bsdf(const PhongSurface& phong) { return !phong.glass; }

}  // namespace rtpro
