#include "interface_bsdf.h"

#include "surface.h"
#include "surface_bsdf.h"

namespace rtpro {

Vec3 bsdf_from(const InterfaceSurface&, const ColorTexture&, const SurfacePoint& point, const TextureLookup*,
               SurfaceBsdf& out) {
  out.bsdf = DielectricBsdf{1.0f, 0.0f};
  out.albedo = Color(0.0f);
  return point.shading_normal;
}

}  // namespace rtpro
