#pragma once
// The Whitted integrator (`whitted`): the Whitted shading model, ambient·C, then per unshadowed light
// C⊙L·max(0,N·L) diffuse plus specular·L·max(0,R·L)^shininess Phong, then the mirror reflection
// traced up to the maximum depth, weighted by the material's reflectivity.
//
// Rays are traced in batches, generation by generation: the camera rays of a batch of samples
// together, then the shadow rays of all their hits together, then all reflection rays, and so on.
// A sample's rays form a tree (a surface may spawn several rays; a light several shadow rays);
// each sample's radiance sums its contributions in a fixed order — by generation, then in the order
// its own rays were spawned — so a pixel never depends on what else shares its batch.
//
// Light linking (scene/light_links.h): a surface takes the direct light of the lights that
// illuminate its object only, and their shadow rays pass the objects that do not cast their
// shadows; mirror and glass rays still see every area light.
//
// Under an open shutter every ray of a sample's tree (camera, shadow, mirror, refraction) is traced
// at the sample's time, so what moves blurs as under the path integrator.
#include "rtpro/backend/backend.h"
#include "camera_batch.h"
#include "rtpro/core/ray.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "rtpro/render/sample_result.h"
#include "rtpro/render/ray_counts.h"
#include "rtpro/render/sampler.h"
#include "hit_prefetch.h"
#include "surface.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

// The buffers one worker reuses from batch to batch (no allocation once warm).
class ShadingWorkspace {
 public:
  // A ray of the current generation and the camera sample it contributes to.
  struct RayTask {
    std::uint32_t sample;
    Color weight;
    // The dielectric material whose interior the ray travels through (absorption over its
    // length), or kOutside.
    std::uint32_t medium = kOutside;
    bool refracted = false;  // counted as a refraction ray
  };
  static constexpr std::uint32_t kOutside = ~0u;
  // A surface the current generation reached, waiting for its shadow rays.
  struct ShadedSurface {
    // Every field is set where a surface is queued; value-initialising the whole record first
    // (emplace_back()) showed up as a zeroing loop in profiles.
    ShadedSurface() {}
    std::uint32_t task;
    SurfacePoint point;
    Color albedo;  // the material's diffuse colour at the point
    Color weight;  // the path weight reaching it (absorption inside glass applied)
    Vec3 mirror;   // unit mirror direction about the shading normal
    // offset_ray_origin_on_side(point, true) where front_origin_known: the shadow rays' batch
    // makes it, and the mirror ray (which leaves by the front) takes it.
    Vec3 front_origin;
    bool front_origin_known;
    std::uint32_t first_shadow;  // its shadow queries are [first_shadow, end_shadow)
    std::uint32_t end_shadow;
  };
  // What one light would add if its shadow ray is unoccluded.
  struct ShadowQuery {
    Color radiance;
    float n_dot_l;
    float r_dot_l;
  };

  struct Generation {
    std::vector<RayTask> tasks;
    std::vector<Ray> rays;
    void clear() {
      tasks.clear();
      rays.clear();
    }
  };

  // A generation as it is read: the first one's rays are the camera batch's own, not a copy.
  struct GenerationView {
    std::span<const RayTask> tasks;
    std::span<const Ray> rays;
  };

  Generation current, next;
  std::vector<Hit> hits;
  std::vector<ShadedSurface> surfaces;
  std::vector<ShadowQuery> shadow_queries;
  std::vector<Ray> shadow_rays;
  std::vector<std::uint32_t> shadow_lights;  // under light linking only: per shadow ray, its light
  std::vector<std::uint8_t> occluded;
  // While the shutter is open: per ray of the current generation and per shadow ray, its sample's
  // time (CameraBatch::times), which every ray of the sample's tree keeps.
  std::vector<float> ray_times, shadow_times;
  // Per light of the scene, set once per batch: its shadow samples per axis, and whether it is an
  // area light that camera and mirror rays can see (also listed in `emitters`).
  std::vector<int> light_samples_per_axis;
  std::vector<std::uint8_t> is_emitter;
  std::vector<std::uint32_t> emitters;
  const TextureLookup* textures = nullptr;        // the scene's image textures, for this batch
  const EnvironmentLight* environment = nullptr;  // the scene's environment, for this batch
};

// The Whitted integrator with its scene and settings. `textures`: the scene's image textures,
// opened (needed only when it has some). `environment`: what rays that escape see (needed only
// when the scene has one); the Whitted integrator shows it but does not light with it.
// `records_primary`: false when nothing reads the primary hits (they are left empty);
// `records_motion`: their film motion is read too (the motion AOV).
class WhittedIntegrator {
 public:
  using Workspace = ShadingWorkspace;
  WhittedIntegrator(const RenderScene& scene, const Backend& backend, const StratifiedSampler& sampler,
                    const TextureLookup* textures, const EnvironmentLight* environment, bool records_primary,
                    bool records_motion)
      : scene_(scene), backend_(backend), sampler_(sampler), textures_(textures), environment_(environment),
        records_primary_(records_primary), records_motion_(records_motion), prefetch_hits_(hit_prefetch_pays(scene)) {}

  // Traces and shades the batch; area lights draw their shadow samples from the sampler with each
  // sample's key. Ray counts are added to `counts`.
  void trace(const CameraBatch& batch, RayCounts& counts, Workspace& workspace) const;

 private:
  const RenderScene& scene_;
  const Backend& backend_;
  const StratifiedSampler& sampler_;
  const TextureLookup* textures_;
  const EnvironmentLight* environment_;
  bool records_primary_;
  bool records_motion_;
  bool prefetch_hits_;  // hit_prefetch_pays(scene)
};

}  // namespace rtpro
