#pragma once
// Lights as the renderer uses them: what arrives from each, worked out once from the scene file's
// description (make_light in build_render_scene.h). Adding a kind means a struct here, an overload
// in src/scene/light.cpp and one in render/light_sample.cpp; every std::visit over Light fails to
// compile until then.
#include "rtpro/core/vec3.h"

#include <variant>

namespace rtpro {

struct PointLight {
  Vec3 position;
  Color radiance;  // colour × intensity; no falloff (the seed's model)
};

struct DirectionalLight {
  Vec3 to_light;   // unit, against the direction light travels in
  Color radiance;  // colour × intensity
};

using Light = std::variant<PointLight, DirectionalLight>;

}  // namespace rtpro
