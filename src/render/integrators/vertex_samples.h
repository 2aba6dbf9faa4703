#pragma once
// The path integrator's fast path for its random numbers: the samples of a generation's vertices
// (every path's vertex at one bounce), made for the whole generation before any of them is shaded.
// The values are the ones a draw per vertex gives, bit for bit; a batch lets the samplers hash
// many keys side by side, the Lambert surfaces' cosine directions run four at a time
// (cosine_lanes.h), and a lone point light's samples four points at a time (point_light_lanes.h).
// Random numbers that nothing in the scene reads are not drawn at all.
#include "light_set.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_scene.h"
#include "sobol_sampler.h"
#include "surface.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

namespace path_dimension {
// Offsets within a bounce's dimensions (sample_dimension::at_bounce).
inline constexpr int kLightPoint = 0;     // and 1
inline constexpr int kBsdfDirection = 2;  // and 3
inline constexpr int kChoices = 4;        // and 5: which light (x) and which BSDF lobe (y)
inline constexpr int kRoulette = 6;
inline constexpr int kMedium = 7;  // the first free path through a medium (render/media/medium_tracking.h)
}  // namespace path_dimension

// The bounce from which a path plays Russian roulette (and draws its number for it).
inline constexpr int kRouletteStart = 3;

// The random numbers of one path vertex.
struct VertexSamples {
  Sample2D choices;         // which light (x) and which BSDF lobe (y)
  Sample2D light_point;     // where on the light
  Sample2D bsdf_direction;  // the BSDF's direction within its lobe
  float roulette;           // from kRouletteStart on: whether the path goes on
  float medium;             // in scenes with media: where the ray reaching the vertex first collides
  // sample_cosine_hemisphere(bsdf_direction), drawn with it when the scene has Lambert surfaces.
  Vec3 cosine_direction;
};

// Which of a vertex's random numbers the scene reads: the choices when its lights need picking or
// a material chooses among lobes, the light point when a light has an extent. Each value is a
// function of its own dimension, so leaving out a draw nothing reads changes no other value.
// The Lambert surfaces' cosine-weighted directions are worked out for every vertex at once when
// some material makes them; the medium's number is drawn when the scene has media.
struct VertexDraws {
  bool choices;
  bool light_point;
  bool cosine_directions;
  bool medium;
};
VertexDraws vertex_draws(const RenderScene& scene, const LightSet& lights);

// The samples of one generation's vertices, vertex i being path i's; the buffers are reused from
// generation to generation.
class GenerationSamples {
 public:
  // The random numbers of the vertices at bounce `bounce`, vertex i's drawn with path_keys[i] (its
  // path's camera sample). A path that reaches no surface leaves its draw unused, and the fields
  // `needed` leaves out keep whatever they held.
  void draw(const StratifiedSampler& sampler, std::span<const SampleKey> path_keys, int bounce, VertexDraws needed);
  // The same; the Sobol sampler draws all of a vertex's dimensions in one pass over the keys
  // (hashing each key once), straight into the records.
  void draw(const SobolSampler& sampler, std::span<const SampleKey> path_keys, int bounce, VertexDraws needed);
  const VertexSamples& operator[](std::size_t vertex) const { return vertices_[vertex]; }

  // The light samples of the vertices at `surfaces` when one point light lights the scene
  // (LightSet::lone_point_light): they depend on nothing but the points. Made for every path, the
  // ones that hit nothing included (their samples go unread).
  void sample_lone_point_light(const LightSet::LonePointLight& lone, std::span<const SurfacePoint> surfaces);
  // The vertex's light sample so made, or null when the light sends nothing there.
  const PathLightSample* lone_light_sample(std::size_t vertex) const {
    return light_found_[vertex] ? &light_samples_[vertex] : nullptr;
  }

 private:
  std::vector<VertexSamples> vertices_;
  std::vector<Sample2D> draws_;
  std::vector<float> roulette_draws_;
  std::vector<PathLightSample> light_samples_;
  std::vector<std::uint8_t> light_found_;
};

}  // namespace rtpro
