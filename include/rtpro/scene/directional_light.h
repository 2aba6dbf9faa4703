#pragma once
// A directional light, the scene's side of the kind in one place (as scene/point_light.h
// explains): reading in src/scene/yaml/yaml_directional_light.cpp, the rest in
// src/scene/build/directional_light.cpp, its shading side in render/lights/directional_light_sample.h.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct YamlNode;
struct SceneSummary;

struct DirectionalLightDesc {
  Vec3 direction{0.0f, -1.0f, 0.0f};  // the direction light travels in
  Color color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
};

struct DirectionalLight {
  Vec3 to_light;   // unit, against the direction light travels in
  Color radiance;  // colour × intensity
};

inline const char* light_type_name(const DirectionalLightDesc&) { return "directional"; }
void read_light_desc(const YamlNode& node, DirectionalLightDesc& desc);
DirectionalLight light_from(const DirectionalLightDesc& desc);
double reach_from_origin(const DirectionalLightDesc& desc);  // 0: it places nothing
void count_light(const DirectionalLight& light, SceneSummary& summary);

}  // namespace rtpro
