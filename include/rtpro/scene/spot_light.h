#pragma once
// A spot light, the scene's side of the kind in one place (as scene/point_light.h explains):
// reading in src/scene/yaml/yaml_spot_light.cpp, the rest in src/scene/build/spot_light.cpp, its
// shading side in render/lights/spot_light_sample.h.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct YamlNode;
struct SceneSummary;

// A point light that shines into a cone around its axis (pbrt-v4's spot light): full intensity
// within inner_angle of the axis, none beyond outer_angle, a smooth step in cos θ between.
struct SpotLightDesc {
  Vec3 position;
  Vec3 direction{0.0f, -1.0f, 0.0f};  // unit: the axis light travels along (`look_at` resolved)
  Color color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;     // on the axis, as a point light's
  float inner_angle = 0.0f;   // degrees off the axis, 0 <= inner_angle <= outer_angle
  float outer_angle = 45.0f;  // degrees, 0 < outer_angle <= 90
};

// A point light whose intensity falls off away from its axis, as pbrt-v4's SpotLight: full within
// the inner cone, none outside the outer one, smoothstep(cos_outer, cos_inner, cos θ) between.
struct SpotLight {
  Vec3 position;
  Vec3 axis;                   // unit: the direction light travels along
  Color radiance;              // colour × intensity, on the axis (as a point light's)
  float cos_inner;             // cosine of the inner cone's half-angle
  float cos_outer;             // cosine of the outer cone's half-angle, <= cos_inner
  bool inverse_square = true;  // as a point light's (scene/point_light.h)

  // The share of `radiance` sent along unit `outward` (from the light): exactly 0 outside the
  // outer cone. Equal cones are a hard edge.
  float falloff(const Vec3& outward) const {
    const float cos_theta = dot(axis, outward);
    if (cos_inner == cos_outer) return cos_theta < cos_outer ? 0.0f : 1.0f;
    float t = (cos_theta - cos_outer) / (cos_inner - cos_outer);
    t = t < 0.0f ? 0.0f : (t > 1.0f ? 1.0f : t);
    return t * t * (3.0f - 2.0f * t);
  }
};

inline const char* light_type_name(const SpotLightDesc&) { return "spot"; }
void read_light_desc(const YamlNode& node, SpotLightDesc& desc);
SpotLight light_from(const SpotLightDesc& desc);
double reach_from_origin(const SpotLightDesc& desc);
void count_light(const SpotLight& light, SceneSummary& summary);

}  // namespace rtpro
