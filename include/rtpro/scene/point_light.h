#pragma once
// A point light, the scene's side of the kind in one place: what a scene file says (`type: point`),
// the light the renderer uses, and the kind's operations, each defined where its machinery lives
// (reading in src/scene/yaml/yaml_point_light.cpp, the rest in src/scene/build/point_light.cpp).
// Its shading side is render/lights/point_light_sample.h; the kind is registered in scene/light.h.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct YamlNode;      // only the scene-file reader (src/scene/yaml/) can call read_light_desc
struct SceneSummary;  // scene/scene_summary.h

struct PointLightDesc {
  Vec3 position;
  Color color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
};

struct PointLight {
  Vec3 position;
  Color radiance;  // colour × intensity, in the scene's light units (scene/render_settings.h)
  // Whether the path integrator divides what arrives by d²: its light set (render/lights/light_set.h)
  // clears it in a scene of whitted light units. The whitted integrator takes the falloff from the
  // units alone.
  bool inverse_square = true;
};

inline const char* light_type_name(const PointLightDesc&) { return "point"; }
// Fills `desc` (defaults on entry) from the scene file's entry, each value checked where it is written.
void read_light_desc(const YamlNode& node, PointLightDesc& desc);
PointLight light_from(const PointLightDesc& desc);
// How far from the origin the light places what rays aim at (the range check's).
double reach_from_origin(const PointLightDesc& desc);
void count_light(const PointLight& light, SceneSummary& summary);

}  // namespace rtpro
