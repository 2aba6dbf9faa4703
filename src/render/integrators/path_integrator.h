#pragma once
// Unidirectional path tracing with multiple importance sampling (the `path` integrator). At every
// vertex whose BSDF is not purely specular, one light sample (LightSet: every light kind and every
// emissive surface) and one BSDF sample, each weighted by the power heuristic against the other's
// pdf; emission reached by a BSDF sample after a specular vertex (or by the camera ray) counts in
// full. Russian roulette after kRouletteStart bounces, on the throughput without refraction's 1/η²
// radiance scale, its number from the sampler.
//
// Media (render/media/): a path's rays are tracked through the medium they travel in by delta
// tracking, which adds the medium's emission and may end the ray at a scattering vertex, where one
// light sample and one Henyey–Greenstein sample are weighted by the power heuristic as at a surface;
// shadow rays are ratio-tracked through media and pass index-matched interfaces (`type:
// interface`), and so does the path's own ray, without a vertex. A scene without media takes none
// of this: one flag tested per vertex.
//
// Light linking (scene/light_links.h): a vertex samples among the lights that illuminate its
// object, and emission a ray from it reaches is weighted by that vertex's pdfs; its shadow rays
// pass the objects that do not cast their light's shadows.
//
// Paths are traced in generations, as the Whitted integrator traces its rays: every path's next ray of a
// batch together, then every shadow ray of that generation together. Each sample's radiance sums
// its contributions in the order its own path made them, so it never depends on what else shares
// its batch; every random decision is a pure function of (pixel, sample, dimension, seed). The
// random numbers of a generation's vertices are drawn for all of them at once (vertex_samples.h).
#include "camera_batch.h"
#include "camera_samplers.h"
#include "rtpro/backend/backend.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/ray_counts.h"
#include "light_set.h"
#include "medium_stack.h"
#include "rtpro/render/sampler.h"
#include "surface.h"
#include "rtpro/scene/render_scene.h"
#include "vertex_samples.h"

#include <cstdint>
#include <vector>

namespace rtpro {

// The buffers one worker reuses from batch to batch.
class PathWorkspace {
 public:
  // 72 bytes, copied from vertex to vertex: the narrow fields are packed together.
  struct Path {
    std::uint32_t sample;
    std::uint16_t bounce;
    // How many of the path's BSDF samples took each kind of lobe (BsdfLobe), and of its phase
    // function samples (volume), for their limits; counted only when a limit is below max_depth.
    std::uint16_t diffuse_bounces, glossy_bounces, transmission_bounces, volume_bounces;
    Color beta;           // throughput from the camera to this ray's origin
    float eta_scale;      // the product of η² of the path's refractions (BsdfSample::eta)
    Vec3 origin;          // the vertex the ray leaves (for the pdf of light sampling)
    float bsdf_pdf;       // solid-angle pdf of the ray's direction
    float min_pdf;        // the least pdf of the path's non-delta BSDF samples (Filter Glossy, when on)
    std::uint32_t group;  // the light-link group of the vertex the ray leaves (0 for the camera)
    MediumStack media;    // the media the ray travels in
    bool specular;        // the ray left a specular vertex or the camera: emission counts in full
    bool aov_pending;     // albedo and normal AOVs wait for the first non-specular vertex
    bool transmitted;     // the ray was refracted into or out of a surface (counted as refraction)

    // This path one bounce on from the vertex its ray reached, along a sampled direction of
    // solid-angle pdf `pdf`: the sample, lobe counters, eta_scale, min_pdf, group, media and
    // pending AOVs carried over, the ray neither specular nor refracted; a vertex that changes
    // any of those sets it on the result.
    Path bounced(const Color& next_beta, const Vec3& vertex, float pdf) const {
      Path next = *this;
      ++next.bounce;
      next.beta = next_beta;
      next.origin = vertex;
      next.bsdf_pdf = pdf;
      next.specular = false;
      next.transmitted = false;
      return next;
    }
  };
  static constexpr std::uint32_t kFound = 0xffffffffu;
  struct ShadowQuery {
    std::uint32_t sample;
    // Added when the shadow ray is unoccluded; β·f alone where `unfound` says the light's
    // radiance and pdf are still to be found (found_contribution).
    Color contribution;
    std::uint32_t unfound = kFound;  // else an index into unfound_lights
  };
  // An environment light sample whose radiance and pdf are left unfound until its shadow ray
  // passes: the contribution is then clamped(β·f·Le·(w_l/p_l), clamp_limit), as for any light
  // sample, with p_l the direction's pdf times the pick's.
  struct UnfoundLight {
    const EnvironmentLight* environment;
    Vec3 direction;
    float pick_pmf;
    float scatter_pdf;  // the BSDF's pdf of the direction, for w_l
    float clamp_limit;  // clamped()'s; infinite where nothing is clamped
  };
  // In a scene with media, where a shadow ray starts: its media, the seed of its ratio tracking,
  // and the scene light it goes to (kInvalidId for an emitter or the environment).
  struct MediumShadow {
    MediumStack media;
    std::uint64_t seed;
    std::uint32_t light;
  };

  std::vector<Path> paths, next_paths;
  std::vector<Ray> rays, next_rays;
  std::vector<Hit> hits;
  std::vector<SurfacePoint> surfaces;  // of the hits, for the hits that are valid
  std::vector<SampleKey> path_keys;    // per path, its camera sample's key
  GenerationSamples samples;           // per path, the samples of the vertex its ray reaches
  std::vector<ShadowQuery> shadow_queries;
  std::vector<UnfoundLight> unfound_lights;
  std::vector<Ray> shadow_rays;
  // Under light linking only: per shadow ray, the scene light it goes to, or kInvalidId.
  std::vector<std::uint32_t> shadow_lights;
  std::vector<std::uint8_t> occluded;
  // While the shutter is open: per ray and per shadow ray, its sample's time (CameraBatch::times).
  std::vector<float> ray_times, shadow_times;
  // In a scene with media only: per shadow ray, where it starts and what it lets through.
  std::vector<MediumShadow> medium_shadows;
  std::vector<Color> shadow_transmittance;
};

// The path integrator with its scene, settings and lights (every light and emissive surface of the
// scene, and its environment when it has one: required then, built from its image). `textures`:
// the scene's image textures, opened (needed only when it has some).
class PathIntegrator {
 public:
  using Workspace = PathWorkspace;
  PathIntegrator(const RenderScene& scene, const Backend& backend, const CameraSamplers& samplers,
                 const TextureLookup* textures, const EnvironmentLight* environment, bool records_motion = false);

  // Traces the batch's paths; each sample's random numbers come from the sampler render.sampler
  // chooses. Ray counts are added to `counts` (bounces as reflection or refraction rays).
  void trace(const CameraBatch& batch, RayCounts& counts, Workspace& workspace) const;

  const LightSet& lights() const { return lights_; }

 private:
  template <class Sampler>
  void trace_with(const Sampler& sampler, const CameraBatch& batch, RayCounts& counts, Workspace& ws) const;

  const RenderScene& scene_;
  const Backend& backend_;
  const CameraSamplers& samplers_;
  const TextureLookup* textures_;
  LightSet lights_;
  VertexDraws draws_;    // which of a vertex's random numbers the scene reads
  bool records_motion_;  // the camera hits' film motion (the motion AOV)
  bool prefetch_hits_;   // hit_prefetch_pays(scene)
};

}  // namespace rtpro
