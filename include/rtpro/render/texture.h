#pragma once
// Evaluating a material's colour texture at a shading point.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/render_scene.h"

namespace rtpro {

// The colour of `texture` at world position `position`.
Color evaluate(const ColorTexture& texture, const Vec3& position);

}  // namespace rtpro
