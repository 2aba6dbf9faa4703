#pragma once
// The shading side of an interface (scene/interface_material.h): a smooth dielectric of index 1,
// which passes every ray straight through. The path integrator crosses interfaces before it asks
// for a BSDF (they are no vertex of a path); this is what any other caller sees.
#include "bsdf_from.h"

namespace rtpro {

struct InterfaceSurface;  // scene/interface_material.h

// As render/bsdf/bsdf_from.h asks of every kind.
Vec3 bsdf_from(const InterfaceSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
inline bool makes_lambert_bsdf(const InterfaceSurface&) { return false; }

}  // namespace rtpro
