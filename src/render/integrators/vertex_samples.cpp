#include "vertex_samples.h"

#include "cosine_lanes.h"
#include "material_bsdf.h"
#include "sample_dimensions.h"
#include "rtpro/core/overloaded.h"

#include <algorithm>

namespace rtpro {

namespace {

// Which materials a surface of the scene uses. A material no surface uses (the default material
// beside a mesh's own, say) must not turn the Lambert fast paths off or add draws.
std::vector<char> materials_in_use(const RenderScene& scene) {
  std::vector<char> used(scene.materials.size(), 0);
  const auto use = [&](std::uint32_t material) {
    if (material < used.size()) used[material] = 1;
  };
  const auto visit_group = [&](const Group& group) {
    for (const Geometry& geometry : group.geometries)
      std::visit(Overloaded{[&](const SphereSet& set) {
                              for (const Sphere& sphere : set.spheres) use(sphere.material);
                            },
                            [&](const TriangleMesh& mesh) {
                              use(mesh.material);
                              for (std::uint32_t material : mesh.triangle_materials) use(material);
                            },
                            [&](const CurveSet& curves) { use(curves.material); },
                            [](const Instance&) {}},  // its prototype's surfaces are visited below
                 geometry);
  };
  visit_group(scene.top);
  for (const Group& prototype : scene.prototypes) visit_group(prototype);
  return used;
}

}  // namespace

VertexDraws vertex_draws(const RenderScene& scene, const LightSet& lights) {
  const std::vector<char> used = materials_in_use(scene);
  const auto any_material = [&](bool (*which)(const Material&)) {
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
      if (used[i] && which(scene.materials[i])) return true;
    return false;
  };
  return {any_material(reads_lobe_choice) || lights.reads_pick_number(), lights.reads_point_numbers(),
          any_material(makes_lambert_bsdf), !scene.media.empty()};
}

namespace {

// sample_cosine_hemisphere of every vertex's BSDF numbers, into its record.
void draw_cosine_directions(std::vector<VertexSamples>& samples) {
  if (samples.empty()) return;
  sample_cosine_hemispheres(samples.size(), &samples.front().bsdf_direction, &samples.front().cosine_direction,
                            sizeof(VertexSamples));
}

}  // namespace

void GenerationSamples::draw(const StratifiedSampler& sampler, std::span<const SampleKey> path_keys, int bounce,
                             VertexDraws needed) {
  const std::size_t n = path_keys.size();
  draws_.resize(n);
  vertices_.resize(n);
  const auto draw = [&](int offset, Sample2D VertexSamples::*field) {
    sampler.sample_2d(path_keys, sample_dimension::at_bounce(bounce, offset), draws_);
    for (std::size_t i = 0; i < n; ++i) vertices_[i].*field = draws_[i];
  };
  // The light's pick and the BSDF's lobe choice as one 2D sample: one draw instead of two.
  if (needed.choices) draw(path_dimension::kChoices, &VertexSamples::choices);
  if (needed.light_point) draw(path_dimension::kLightPoint, &VertexSamples::light_point);
  draw(path_dimension::kBsdfDirection, &VertexSamples::bsdf_direction);
  if (needed.cosine_directions) draw_cosine_directions(vertices_);
  if (needed.medium) {
    roulette_draws_.resize(n);
    sampler.sample_1d(path_keys, sample_dimension::at_bounce(bounce, path_dimension::kMedium), roulette_draws_);
    for (std::size_t i = 0; i < n; ++i) vertices_[i].medium = roulette_draws_[i];
  }
  if (bounce < kRouletteStart) return;
  roulette_draws_.resize(n);
  sampler.sample_1d(path_keys, sample_dimension::at_bounce(bounce, path_dimension::kRoulette), roulette_draws_);
  for (std::size_t i = 0; i < n; ++i) vertices_[i].roulette = roulette_draws_[i];
}

void GenerationSamples::draw(const SobolSampler& sampler, std::span<const SampleKey> path_keys, int bounce,
                             VertexDraws needed) {
  const std::size_t n = path_keys.size();
  if (n == 0) return;  // the draws below point at the first record
  vertices_.resize(n);
  VertexSamples* const first = vertices_.data();
  const auto pair = [&](int offset, Sample2D VertexSamples::*field) {
    return SobolSampler::Draw<Sample2D>{sample_dimension::at_bounce(bounce, offset), &(first->*field),
                                        sizeof(VertexSamples)};
  };
  // The light's pick and the BSDF's lobe choice as one 2D sample: one draw instead of two.
  SobolSampler::Draw<Sample2D> pairs[3];
  std::size_t pair_count = 0;
  if (needed.choices) pairs[pair_count++] = pair(path_dimension::kChoices, &VertexSamples::choices);
  if (needed.light_point) pairs[pair_count++] = pair(path_dimension::kLightPoint, &VertexSamples::light_point);
  pairs[pair_count++] = pair(path_dimension::kBsdfDirection, &VertexSamples::bsdf_direction);
  SobolSampler::Draw<float> singles[2];
  std::size_t single_count = 0;
  if (needed.medium)
    singles[single_count++] = {sample_dimension::at_bounce(bounce, path_dimension::kMedium), &first->medium,
                               sizeof(VertexSamples)};
  if (bounce >= kRouletteStart)
    singles[single_count++] = {sample_dimension::at_bounce(bounce, path_dimension::kRoulette), &first->roulette,
                               sizeof(VertexSamples)};
  sampler.sample(path_keys, {pairs, pair_count}, {singles, single_count});
  if (needed.cosine_directions) draw_cosine_directions(vertices_);
}

void GenerationSamples::sample_lone_point_light(const LightSet::LonePointLight& lone,
                                                std::span<const SurfacePoint> surfaces) {
  light_samples_.resize(surfaces.size());
  light_found_.resize(surfaces.size());
  LightSet::sample_lone_point_light(lone, surfaces, light_samples_, light_found_);
}

}  // namespace rtpro
