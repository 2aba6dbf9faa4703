#pragma once
// A material's BSDF at a shading point and the frame it is evaluated in: what each kind's
// bsdf_from (render/bsdf/bsdf_from.h) writes.
#include "bsdf.h"
#include "shading_frame.h"

namespace rtpro {

struct SurfaceBsdf {
  Bsdf bsdf;
  // +z is the shading normal: on the side the ray came from for opaque kinds, which have no
  // inside; on the outside (the side the primitive's normal points to) for dielectrics, whose
  // BSDF tells entering from leaving.
  ShadingFrame frame;
  Color albedo;  // what the albedo AOV shows: the base colour of the model at the point
};

// A Lambert surface of `reflectance`, which is its albedo too: what several kinds make (in their
// bsdf_from). Returns `normal`.
inline Vec3 lambert_surface(const Color& reflectance, const Vec3& normal, SurfaceBsdf& out) {
  out.bsdf = DiffuseBsdf{reflectance};
  out.albedo = reflectance;
  return normal;
}

}  // namespace rtpro
