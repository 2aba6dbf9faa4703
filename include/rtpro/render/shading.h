#pragma once
// The shading model (the seed's, completed): ambient·C, then per unshadowed light
// C⊙L·max(0,N·L) diffuse plus specular·L·max(0,R·L)^shininess Phong, then the mirror reflection
// traced up to the maximum depth, weighted by the material's reflectivity.
#include "rtpro/backend/backend.h"
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>

namespace rtpro {

struct RayCounts {
  std::uint64_t camera = 0;
  std::uint64_t shadow = 0;
  std::uint64_t reflection = 0;
  std::uint64_t total() const { return camera + shadow + reflection; }
  RayCounts& operator+=(const RayCounts& o) {
    camera += o.camera;
    shadow += o.shadow;
    reflection += o.reflection;
    return *this;
  }
};

// What the camera ray itself hit: the sources of the AOV passes.
struct PrimaryHit {
  bool hit = false;
  Color albedo;
  Vec3 normal;          // shading normal, world space, unit
  float depth = 0.0f;   // distance from the camera
  std::uint32_t object_id = 0;
};

Color trace_radiance(const RenderScene& scene, const Backend& backend, const Ray& camera_ray, RayCounts& counts,
                     PrimaryHit* primary = nullptr);

// The same, for a camera ray whose closest hit was already traced (camera rays go to the backend
// in batches); `camera_hit` is used only when `camera_hit_found`.
Color trace_radiance_from(const RenderScene& scene, const Backend& backend, const Ray& camera_ray,
                          bool camera_hit_found, const Hit& camera_hit, RayCounts& counts, PrimaryHit* primary);

}  // namespace rtpro
