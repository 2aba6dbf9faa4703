#include "path_integrator.h"

#include "material_bsdf.h"

#include "light_linking.h"
#include "medium_shadows.h"
#include "path_vertex_step.h"
#include "sample_times.h"
#include "hit_prefetch.h"
#include "surface_batch.h"

#include <limits>
#include <optional>

namespace rtpro {

namespace {

using Path = PathWorkspace::Path;

// Every camera ray as the first ray of its sample's path, every result cleared.
void start_camera_paths(const CameraBatch& batch, PathWorkspace& ws) {
  ws.paths.clear();
  ws.rays.assign(batch.rays.begin(), batch.rays.end());
  for (std::uint32_t i = 0; i < batch.rays.size(); ++i) {
    batch.results[i] = SampleResult{};
    // Written in place a field at a time: a Path built as a temporary and pushed is copied with
    // wide loads over the narrow stores that have just built it, a store-forwarding stall per path.
    Path& path = ws.paths.emplace_back();
    path.sample = i;
    path.bounce = 0;
    path.diffuse_bounces = 0;
    path.glossy_bounces = 0;
    path.transmission_bounces = 0;
    path.volume_bounces = 0;
    path.beta = Color(1.0f);
    path.eta_scale = 1.0f;
    path.origin = batch.rays[i].org;
    path.bsdf_pdf = 0.0f;
    path.min_pdf = std::numeric_limits<float>::infinity();
    path.group = 0;
    path.media = {};
    path.specular = true;
    path.aov_pending = true;
    path.transmitted = false;
  }
}

// Each path's camera sample key, for its vertex's draws.
std::span<const SampleKey> path_keys(std::span<const SampleKey> keys, PathWorkspace& ws) {
  ws.path_keys.resize(ws.paths.size());
  for (std::size_t i = 0; i < ws.paths.size(); ++i) ws.path_keys[i] = keys[ws.paths[i].sample];
  return ws.path_keys;
}

}  // namespace

PathIntegrator::PathIntegrator(const RenderScene& scene, const Backend& backend, const CameraSamplers& samplers,
                               const TextureLookup* textures, const EnvironmentLight* environment, bool records_motion)
    : scene_(scene), backend_(backend), samplers_(samplers), textures_(textures), lights_(scene, environment),
      draws_(vertex_draws(scene, lights_)), records_motion_(records_motion), prefetch_hits_(hit_prefetch_pays(scene)) {
  prepare_material_bsdfs(scene);
}

void PathIntegrator::trace(const CameraBatch& batch, RayCounts& counts, Workspace& ws) const {
  samplers_.with_chosen([&](const auto& sampler) { trace_with(sampler, batch, counts, ws); });
}

template <class Sampler>
void PathIntegrator::trace_with(const Sampler& sampler, const CameraBatch& batch, RayCounts& counts,
                                Workspace& ws) const {
  const RenderScene& scene = scene_;
  start_camera_paths(batch, ws);
  counts[RayKind::kCamera] += batch.rays.size();
  // Asked per batch, not kept: it points into lights_, which a copy of the integrator would not
  // share. Its samples are made at the surfaces a generation reaches, which a path tracked through
  // media and interfaces may stop short of or pass.
  std::optional<LightSet::LonePointLight> lone_point_light = lights_.lone_point_light();
  if (draws_.medium) lone_point_light.reset();
  PathVertexStep<true> controlled_step(scene, backend_, lights_, batch.results, ws, textures_, draws_.cosine_directions,
                                       lone_point_light.has_value(), records_motion_);
  PathVertexStep<false> plain_step(scene, backend_, lights_, batch.results, ws, textures_, draws_.cosine_directions,
                                   lone_point_light.has_value(), records_motion_);
  const bool controlled = controlled_step.controls_apply();
  const auto extend_generation = [&](auto& step) {
    if (draws_.medium)
      for (std::size_t i = 0; i < ws.paths.size(); ++i)
        step.extend_through_media(i, ws.paths[i], ws.rays[i], ws.hits[i], ws.surfaces[i], ws.samples[i]);
    else
      for (std::size_t i = 0; i < ws.paths.size(); ++i)
        step.extend(i, ws.paths[i], ws.rays[i], ws.hits[i], ws.surfaces[i], ws.samples[i]);
  };
  for (int generation = 0; !ws.paths.empty(); ++generation) {
    ws.hits.resize(ws.rays.size());
    times_of_samples(
        batch.times, std::span<const Path>(ws.paths), [](const Path& path) { return path.sample; }, ws.ray_times);
    backend_.intersect(ws.rays, ws.ray_times, ws.hits,
                       generation == 0 ? RayCoherence::kCoherent : RayCoherence::kIncoherent);
    ws.next_paths.clear();
    ws.next_rays.clear();
    ws.shadow_queries.clear();
    ws.unfound_lights.clear();
    ws.shadow_rays.clear();
    ws.shadow_lights.clear();
    ws.medium_shadows.clear();
    ws.surfaces.resize(ws.rays.size());
    make_surfaces(scene, prefetch_hits_, ws.rays, ws.ray_times, ws.hits, ws.surfaces);
    // Media track every generation's rays, the last's too, with the vertex's numbers.
    if (generation < scene.render.max_depth || draws_.medium) {
      ws.samples.draw(sampler, path_keys(batch.keys, ws), generation, draws_);
      if (lone_point_light) ws.samples.sample_lone_point_light(*lone_point_light, ws.surfaces);
    }
    if (controlled) extend_generation(controlled_step);
    else extend_generation(plain_step);

    times_of_samples(
        batch.times, std::span<const PathWorkspace::ShadowQuery>(ws.shadow_queries),
        [](const PathWorkspace::ShadowQuery& q) { return q.sample; }, ws.shadow_times);
    counts[RayKind::kShadow] += ws.shadow_rays.size();
    if (draws_.medium) {
      ws.shadow_transmittance.resize(ws.shadow_rays.size());
      medium_shadow_transmittance(backend_, scene, ws.shadow_rays, ws.shadow_times, ws.medium_shadows,
                                  ws.shadow_transmittance);
      for (std::size_t i = 0; i < ws.shadow_queries.size(); ++i)
        if (Color contribution; found_contribution(ws.shadow_queries[i], ws, scene.render.path_sampling, contribution))
          batch.results[ws.shadow_queries[i].sample].radiance += contribution * ws.shadow_transmittance[i];
    } else {
      ws.occluded.resize(ws.shadow_rays.size());
      occluded_with_shadow_linking(backend_, scene.links, ws.shadow_rays, ws.shadow_times, ws.shadow_lights,
                                   ws.occluded, RayCoherence::kIncoherent);
      for (std::size_t i = 0; i < ws.shadow_queries.size(); ++i)
        if (Color contribution;
            !ws.occluded[i] && found_contribution(ws.shadow_queries[i], ws, scene.render.path_sampling, contribution))
          batch.results[ws.shadow_queries[i].sample].radiance += contribution;
    }
    // Summed in a local: a store to the counts in the loop would reload every path's field.
    std::uint64_t transmitted = 0;
    for (const Path& next : ws.next_paths) transmitted += next.transmitted;
    counts[RayKind::kRefraction] += transmitted;
    counts[RayKind::kReflection] += ws.next_paths.size() - transmitted;
    std::swap(ws.paths, ws.next_paths);
    std::swap(ws.rays, ws.next_rays);
  }
}

}  // namespace rtpro
