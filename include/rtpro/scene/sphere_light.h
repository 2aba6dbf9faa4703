#pragma once
// A sphere light, the scene's side of the kind in one place (as scene/point_light.h explains):
// reading in src/scene/yaml/yaml_sphere_light.cpp, the rest in src/scene/build/sphere_light.cpp,
// its shading side in render/lights/sphere_light_sample.h.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct YamlNode;
struct SceneSummary;

// Area lights emit `color` × `intensity` as radiance from their surface, falling off with distance
// as a real light does; each shading point sends samples × samples stratified shadow rays to one.
struct SphereLightDesc {
  Vec3 center;
  float radius = 1.0f;
  Color color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
  int samples = 4;
};

// A sphere that emits `radiance` from its surface; shading samples the cone it fills as seen from
// the point, samples_per_axis² stratified directions.
struct SphereLight {
  Vec3 center;
  float radius;
  Color radiance;
  int samples_per_axis;
};

inline const char* light_type_name(const SphereLightDesc&) { return "sphere"; }
void read_light_desc(const YamlNode& node, SphereLightDesc& desc);
SphereLight light_from(const SphereLightDesc& desc);
double reach_from_origin(const SphereLightDesc& desc);
void count_light(const SphereLight& light, SceneSummary& summary);

}  // namespace rtpro
