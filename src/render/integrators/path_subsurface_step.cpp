// The path integrator's step under a surface (path_vertex_step.h): a vertex that took its
// material's subsurface lobe walks through the medium under it (subsurface_walk.h), and the path
// goes on from where the walk leaves, with a light sample and a Lambert sample there.
#include "path_vertex_step.h"

#include "light_linking.h"
#include "ray_offset.h"
#include "rtpro/core/append_ray.h"
#include "rtpro/core/random.h"
#include "subsurface_walk.h"

#include <bit>
#include <cmath>
#include <variant>

namespace rtpro {

namespace {

// The walk's stream: the vertex's sample key and its BSDF numbers, so a walk is a pure function
// of (pixel, sample, dimension, seed) like every other random decision.
std::uint64_t walk_seed(const SampleKey& key, const VertexSamples& u) {
  const std::uint64_t sample = hash_combine(key.pixel_key, static_cast<std::uint64_t>(key.sample_index));
  return hash_combine(hash_combine(sample, std::bit_cast<std::uint32_t>(u.bsdf_direction.x)),
                      std::bit_cast<std::uint32_t>(u.bsdf_direction.y)) ^
         0x55b5u;
}

}  // namespace

template <bool kLightPathControls>
void PathVertexStep<kLightPathControls>::walk_under_surface(std::size_t vertex, const Path& path,
                                                            const SurfacePoint& sp, const BsdfSample& entry,
                                                            const VertexSamples& u, const Color& beta,
                                                            const MediumStack& media, bool aov_pending) {
  const Material& material = scene_.materials[sp.material];
  const auto* model = std::get_if<PrincipledSurface>(&material.model);
  if (!model) return;  // only the principled kind has a subsurface lobe
  // In along a cosine-weighted direction about the inward normal (Cycles' entry, a diffuse
  // transmission), and never along the surface's own tangent plane.
  Vec3 local = sample_cosine_hemisphere(u.bsdf_direction);
  if (entry.wi.z < 0.0f) local.z = -local.z;
  const Vec3 direction = surface_.frame.to_world(local);
  if (!(dot(direction, sp.geometric_normal) < 0.0f)) return;
  const SubsurfaceMedium medium = subsurface_media_.get(
      surface_.albedo, model->subsurface_radius, model->subsurface_anisotropy, model->ior, model->subsurface_method);
  const std::uint64_t seed = walk_seed(ws_.path_keys[vertex], u);
  TrackingRandom random(seed);
  // The path's time under an open shutter: the walk and its exit are where the path's rays meet.
  const std::optional<float> time = ws_.ray_times.empty() ? std::nullopt : std::optional(ws_.ray_times[vertex]);
  const std::optional<SubsurfaceExit> exit =
      subsurface_walk(backend_, medium, spawn_ray(sp, direction), time, beta * entry.f * (1.0f / entry.pdf), random);
  if (!exit) return;

  // The exit: a white Lambert lobe on the surface's far side from the walk.
  SurfacePoint& out = exit_surface_;
  if (time) make_surface_at(scene_, exit->ray, *time, exit->hit, out);
  else make_surface(scene_, exit->ray, exit->hit, out);
  SurfaceBsdf& lobe = surface_;
  lambert_surface(Color(1.0f), out.shading_normal, lobe);
  lobe.frame = ShadingFrame::from_normal(out.shading_normal);
  const Vec3 wo{0.0f, 0.0f, -1.0f};  // out of the surface, away from the walk
  SpawnOrigins origins(out);
  const std::uint32_t group = link_group_of(scene_.links, exit->hit);
  const float u_pick = random.next();
  const Sample2D u_light{random.next(), random.next()};
  if (!lights_.empty(group) && lights_.sample(out.position, u_pick, u_light, textures_, group, light_sample_)) {
    const std::size_t queued = ws_.shadow_queries.size();
    queue_light_sample(path.sample, origins, lobe, wo, light_sample_, exit->beta,
                       path.bounce == 0 ? direct_limit_ : indirect_limit_);
    if (has_media_ && ws_.shadow_queries.size() > queued)
      queue_medium_shadow(media, seed ^ 0x5ad0, light_sample_.light);
  }
  const Sample2D u_direction{random.next(), random.next()};
  const std::optional<BsdfSample> bs = bsdf_sample(lobe.bsdf, wo, 0.0f, u_direction);
  if (!bs || !(bs->pdf > 0.0f)) return;
  // Then on as from any Lambert vertex: roulette, and one more diffuse bounce.
  Color next_beta = exit->beta * bs->f * (std::fabs(bs->wi.z) / bs->pdf);
  if (path.bounce >= kRouletteStart && !russian_roulette(next_beta, path.eta_scale, u.roulette)) return;
  if (!is_finite(next_beta) || carries_no_light(next_beta)) return;
  Path& next = ws_.next_paths.emplace_back(path.bounced(next_beta, out.position, bs->pdf));
  next.group = group;
  next.media = media;
  next.aov_pending = aov_pending;
  if (kLightPathControls && filtering_glossy_) next.min_pdf = std::min(path.min_pdf, bs->pdf);
  if (kLightPathControls && lobe_limits_) ++next.diffuse_bounces;
  append_ray(ws_.next_rays, spawn_ray(origins, lobe.frame.to_world(bs->wi)));
}

template void PathVertexStep<true>::walk_under_surface(std::size_t, const Path&, const SurfacePoint&, const BsdfSample&,
                                                       const VertexSamples&, const Color&, const MediumStack&, bool);
template void PathVertexStep<false>::walk_under_surface(std::size_t, const Path&, const SurfacePoint&,
                                                        const BsdfSample&, const VertexSamples&, const Color&,
                                                        const MediumStack&, bool);

}  // namespace rtpro
