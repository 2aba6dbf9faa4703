#pragma once
// A quad light, the scene's side of the kind in one place (as scene/point_light.h explains):
// reading in src/scene/yaml/yaml_quad_light.cpp, the rest in src/scene/build/quad_light.cpp, its
// shading side in render/lights/quad_light_sample.h.
#include "rtpro/core/vec3.h"

namespace rtpro {

struct YamlNode;
struct SceneSummary;

// A parallelogram centred on `position` with full edges `edge1` and `edge2`, emitting on the side
// of edge1 × edge2 only (an area light, as scene/sphere_light.h describes).
struct QuadLightDesc {
  Vec3 position;
  Vec3 edge1{1.0f, 0.0f, 0.0f};
  Vec3 edge2{0.0f, 0.0f, 1.0f};
  Color color{1.0f, 1.0f, 1.0f};
  float intensity = 1.0f;
  int samples = 4;
};

// A one-sided parallelogram: corner + [0,1]·edge1 + [0,1]·edge2, emitting towards `normal`
// (unit edge1 × edge2); sampled uniformly by area, samples_per_axis² stratified points.
struct QuadLight {
  Vec3 corner, edge1, edge2;
  Vec3 normal;
  float area;
  Color radiance;
  int samples_per_axis;
};

inline const char* light_type_name(const QuadLightDesc&) { return "quad"; }
void read_light_desc(const YamlNode& node, QuadLightDesc& desc);
QuadLight light_from(const QuadLightDesc& desc);
double reach_from_origin(const QuadLightDesc& desc);
void count_light(const QuadLight& light, SceneSummary& summary);

}  // namespace rtpro
