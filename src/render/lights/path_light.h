#pragma once
// A light of the path integrator's set (LightSet): one of the scene's kinds of light, an emissive
// triangle or sphere, or the environment, and what the set asks of each: the power it is picked
// by, its bounds in the light tree, a sample of it seen from a point and that sample's pdf, and
// where camera and BSDF rays meet the lights without geometry.
#include "rtpro/core/ray.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "light_tree.h"
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_scene.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <variant>

namespace rtpro {

// A triangle of an emissive material: p0 + [0,1]·e1 + [0,1]·e2 with barycentrics summing to <= 1.
struct EmissiveTriangle {
  Vec3 p0, e1, e2;
  Vec3 normal;  // unit e1 × e2: the front side
  float area;
  Emission emission;
  std::array<TexCoord, 3> uv{};  // at p0, p0 + e1, p0 + e2 (the mesh's, or its barycentrics)
};

// A sphere of an emissive material (outside: the front side). A textured one is in the frame its
// texture coordinates are defined in (it is not instanced: see render/lights/light_set.h).
struct EmissiveSphere {
  Vec3 center;
  float radius;
  Emission emission;
};

// The scene's environment, owned by whoever built it (it outlives the set).
struct EnvironmentRef {
  const EnvironmentLight* light;
};

// Point and spot lights fall off with the square of distance here (`radiance` read as intensity in
// W/sr, as every physically based renderer reads it), unless the scene's light units are whitted's:
// then path_light_of has made every light π times brighter and point and spot lights constant.
// The scene's kinds of light (scene/light.h) first, in their order, then the emitters.
template <typename Lights, typename... Emitters>
struct WithEmitters;
template <typename... Lights, typename... Emitters>
struct WithEmitters<std::variant<Lights...>, Emitters...> {
  using type = std::variant<Lights..., Emitters...>;
};
using PathLight = WithEmitters<Light, EmissiveTriangle, EmissiveSphere, EnvironmentRef>::type;

struct PathLightSample {
  Vec3 direction;       // unit, from the point towards the light
  float distance;       // to the sampled point; infinity for directional lights and the environment
  Color radiance;       // arriving along `direction` (no pdf folded in); unset where `environment` is
  float pdf;            // solid angle, times the probability of picking the light; 1 for delta lights
  bool delta;           // point, spot and directional lights: no BSDF sample can reach them
  std::uint32_t light;  // which light of the set
  // An environment sample taken with EnvironmentRadiance::kLater, its radiance and the pdf of its
  // direction still to be found (environment->radiance(direction), ->pdf(direction)), once its
  // shadow ray passes: `pdf` is then the pick's probability alone, and the sample may turn out
  // to be none (a direction of pdf 0, which kNow would not have given). Null for every other
  // sample.
  const EnvironmentLight* environment;
};

// Whether an environment sample finds its radiance and pdf at once, or leaves them to the caller
// (PathLightSample::environment): inside a room most environment samples' shadow rays are
// stopped, and finding them is a cache miss or two, an atan2 and an acos.
enum class EnvironmentRadiance : std::uint8_t { kNow, kLater };

// A scene light as the path integrator reads it in a scene of light units `units`.
PathLight path_light_of(const Light& light, LightUnits units);

// The power (the average of its channels) the set picks the light by; `scene_radius` sizes what
// directional lights and the environment deliver.
float path_light_power(const PathLight& light, float scene_radius);
// Where the light is and which way it shines, for the light tree; nothing for lights without a
// position. `power` is path_light_power's.
std::optional<LightBounds> path_light_bounds(const PathLight& light, float power);
// A point light seen from `from`, as sample_path_light samples one: into `out` (not `light`);
// false when `from` is at the light.
inline bool sample_point_light(const PointLight& light, const Vec3& from, PathLightSample& out) {
  const Vec3 to_light = light.position - from;
  const float d2 = dot(to_light, to_light);
  if (!(d2 > 0.0f)) return false;
  const float d = std::sqrt(d2);
  // One division each, multiplied through: a vector divided by a scalar is three divisions in
  // a row on every path vertex.
  out.direction = to_light * (1.0f / d);
  out.distance = d;
  out.radiance = light.inverse_square ? light.radiance * (1.0f / d2) : light.radiance;
  out.pdf = 1.0f;
  out.delta = true;
  out.environment = nullptr;
  return true;
}

// sample_path_light for a light of any kind, out of line.
bool sample_path_light_of_any_kind(const PathLight& light, const Vec3& from, Sample2D u, const TextureLookup* textures,
                                   PathLightSample& out, EnvironmentRadiance environment = EnvironmentRadiance::kNow);

// A point of the light by `u`, seen from `from`, into `out` (its direction, distance, radiance,
// pdf and whether it is a delta light; not `light`); false when the light sends nothing there.
// Point lights inline: a scene lit by them samples one at every path vertex, and a point light's
// sample costs less than a call.
inline bool sample_path_light(const PathLight& light, const Vec3& from, Sample2D u, const TextureLookup* textures,
                              PathLightSample& out, EnvironmentRadiance environment = EnvironmentRadiance::kNow) {
  if (const auto* point = std::get_if<PointLight>(&light)) return sample_point_light(*point, from, out);
  return sample_path_light_of_any_kind(light, from, u, textures, out, environment);
}
// The solid-angle pdf of sample_path_light reaching `on_light` from `from`; 0 for delta lights.
float path_light_pdf(const PathLight& light, const Vec3& from, const Vec3& on_light);
// Whether camera and BSDF rays can meet the light itself (sphere and quad lights; the backend
// finds the emissive surfaces).
bool met_by_rays(const PathLight& light);
// Whether sample_path_light reads its `u` (lights with an extent; a point, spot or directional
// light has one direction to give, whatever `u`).
bool samples_by_number(const PathLight& light);
// Where `ray` meets a light met_by_rays says rays meet, before t_max (`seen`: its radiance there),
// or kLightMissed (hit_light, render/lights/light_sample.h).
float meet_path_light(const PathLight& light, const Ray& ray, float t_max, Color& seen);

}  // namespace rtpro
