#pragma once
// A material's BSDF at a shading point, and the frame it is evaluated in: each kind of surface
// model (SurfaceModel, scene/material_kinds.h) makes its BSDF in its own bsdf_from
// (render/bsdf/conductor_bsdf.h and its neighbours, registered in render/bsdf/bsdf.h).
#include "rtpro/image/texture_lookup.h"
#include "bsdf.h"
#include "shading_frame.h"
#include "surface.h"
#include "rtpro/scene/render_scene.h"

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

// Whether the material's BSDF is a DiffuseBsdf (lambert_surface) wherever it is hit.
bool makes_lambert_bsdf(const Material& material);
// Whether the BSDF the material makes reads bsdf_sample's u_lobe: all but a Lambert surface's,
// whose one lobe needs no choosing (a vertex's random numbers that nothing reads need not be
// drawn).
inline bool reads_lobe_choice(const Material& material) { return !makes_lambert_bsdf(material); }

// `textures`: the scene's image textures, opened, for the colour textures the material reads.
// Written into `out`, whose previous contents do not matter.
void material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures,
                   SurfaceBsdf& out);
inline SurfaceBsdf material_bsdf(const Material& material, const SurfacePoint& point, const TextureLookup* textures) {
  SurfaceBsdf surface;
  material_bsdf(material, point, textures, surface);
  return surface;
}

}  // namespace rtpro
