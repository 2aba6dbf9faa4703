#pragma once
// The kinds of light, registered: each kind's scene side is one header (its scene-file
// description, the light the renderer uses, and its operations: see scene/point_light.h) and its
// shading side another (render/lights/point_light_sample.h, registered in render/lights/light_sample.h). A new
// kind is a header here, an alternative in each variant below and its include; every std::visit
// over LightDesc or Light then names the operations it still lacks.
#include "rtpro/scene/directional_light.h"
#include "rtpro/scene/point_light.h"
#include "rtpro/scene/quad_light.h"
#include "rtpro/scene/sphere_light.h"
#include "rtpro/scene/spot_light.h"

#include <variant>

namespace rtpro {

// What the scene file says (scene/description.h), in the order the kinds are listed in its docs.
using LightDesc = std::variant<PointLightDesc, SpotLightDesc, DirectionalLightDesc, SphereLightDesc, QuadLightDesc>;

// Lights as the renderer uses them: what arrives from each, worked out once from the scene file's
// description (make_light in build_render_scene.h), in LightDesc's order.
using Light = std::variant<PointLight, SpotLight, DirectionalLight, SphereLight, QuadLight>;

}  // namespace rtpro
