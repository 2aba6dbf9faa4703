#pragma once
// The kinds of material, registered: each kind's scene side is one header (its parameters, its
// `type:` and keys, its surface model and its Whitted approximation: see scene/phong_material.h)
// and its shading side another (render/phong_bsdf.h, registered in render/bsdf.h). A new kind is a
// header here, an alternative in each variant below and its include; every std::visit over
// MaterialParams or SurfaceModel then names the operations it still lacks.
#include "rtpro/scene/conductor_material.h"
#include "rtpro/scene/dielectric_material.h"
#include "rtpro/scene/diffuse_material.h"
#include "rtpro/scene/phong_material.h"
#include "rtpro/scene/principled_material.h"

#include <variant>

namespace rtpro {

// What the scene file says of a material besides what every kind has (MaterialDesc), in the order
// its messages list the kinds.
using MaterialParams = std::variant<PhongParams, DiffuseParams, ConductorParams, DielectricParams, PrincipledParams>;

// What the path integrator evaluates at a surface (render/material_bsdf.h makes its BSDF), in
// MaterialParams' order.
using SurfaceModel = std::variant<PhongSurface, DiffuseSurface, ConductorSurface, DielectricSurface, PrincipledSurface>;

}  // namespace rtpro
