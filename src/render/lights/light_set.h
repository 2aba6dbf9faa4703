#pragma once
// Every light the path integrator samples: the scene's lights and its emissive surfaces (each
// emissive triangle and sphere a light of its own, in world space, instances included), picked in
// proportion to their power and sampled with an exact pdf, so a BSDF sample that reaches one of
// them can be weighted against light sampling (multiple importance sampling).
//
// An emissive sphere under a transform that does not scale uniformly is an ellipsoid and is not
// sampled: a path that hits one adds its emission with weight 1, which is unbiased (BSDF sampling
// alone), only noisier. Nor is an instanced sphere with an emission texture, whose texture
// coordinates are those of its prototype's frame.
//
// Light linking (scene/light_links.h): each link group of objects picks among the lights that
// illuminate it (a LightPicker of its own, shared by groups lit by the same lights). The calls
// below take the group of the shading point (of the vertex a ray left, for emission it reaches);
// group 0, every light, is also what a scene without linking and a camera ray have.
#include "rtpro/backend/hit.h"
#include "rtpro/core/ray.h"
#include "rtpro/image/texture_lookup.h"
#include "rtpro/render/environment_light.h"
#include "light_picker.h"
#include "path_light.h"
#include "rtpro/render/sampler.h"
#include "surface.h"
#include "rtpro/scene/render_scene.h"

#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <variant>
#include <vector>

namespace rtpro {

// The most lights all link groups' light pickers may hold together (each distinct set of
// illuminating lights one picker over its members); a scene above it is refused (scenes/FORMAT.md).
inline constexpr std::uint64_t kMaxLinkedLightEntries = std::uint64_t{1} << 21;

class LightSet {
 public:
  // `environment`: the scene's, built from its image (required when the scene has one). Throws
  // InputError when light linking asks for more than kMaxLinkedLightEntries.
  explicit LightSet(const RenderScene& scene, const EnvironmentLight* environment = nullptr);

  // No light illuminates the group's objects.
  bool empty(std::uint32_t group = 0) const { return picker(group).empty(); }
  // The scene's lights first (in its order: a scene light's index here is its index there), then
  // its emissive surfaces, then the environment.
  const std::vector<PathLight>& lights() const { return lights_; }

  // A light picked by u_pick, then a point on it by u, as seen from `point`; nothing when the
  // light sends nothing there (behind a one-sided emitter).
  // `textures`: the scene's images, for emitters with an emission texture.
  std::optional<PathLightSample> sample(const Vec3& point, float u_pick, Sample2D u,
                                        const TextureLookup* textures = nullptr, std::uint32_t group = 0) const {
    PathLightSample s;
    return sample(point, u_pick, u, textures, group, s) ? std::optional<PathLightSample>(s) : std::nullopt;
  }
  // The same into `out` (its fields undefined when there is none), for the path integrator's loop.
  // Inline, the pick and a point light's sample with it: every path vertex asks.
  // `environment`: whether an environment sample's radiance and pdf are found now or left to the caller.
  bool sample(const Vec3& point, float u_pick, Sample2D u, const TextureLookup* textures, std::uint32_t group,
              PathLightSample& out, EnvironmentRadiance environment = EnvironmentRadiance::kNow) const {
    LightPicker::Pick pick;
    if (!picker(group).pick(point, u_pick, pick)) return false;
    if (!sample_path_light(lights_[pick.light], point, u, textures, out, environment)) return false;
    out.pdf *= pick.pmf;
    out.light = pick.light;
    return true;
  }

  // The light sample() picks from every point, when it picks without a number (one light, no
  // linking) and that light is a point light: its index and pick probability, or nothing. Its
  // samples then depend only on the points, and sample_lone_point_light makes them for many points
  // at once.
  struct LonePointLight {
    const PointLight* light;
    std::uint32_t index;
    float pmf;
  };
  std::optional<LonePointLight> lone_point_light() const;
  // sample(points[i].position, ...) into out[i] for every i, with found[i] whether there is one,
  // the same bit for bit, four points at a time (point_light_batch.h); `lone` is lone_point_light().
  static void sample_lone_point_light(const LonePointLight& lone, std::span<const SurfacePoint> points,
                                      std::span<PathLightSample> out, std::span<std::uint8_t> found);

  // Whether sample() reads its u_pick (some group's lights are more than one), and its u (some
  // light has an extent): a vertex's random numbers that nothing reads need not be drawn.
  bool reads_pick_number() const;
  bool reads_point_numbers() const;

  // The light that an emissive surface hit is (kInvalidId when it is not sampled).
  std::uint32_t light_of_hit(const Hit& hit) const;
  // The pdf sample() has of reaching `on_light` on light `index` from `from` (solid angle, pick
  // probability included), 0 for lights that cannot be hit or do not illuminate the group.
  float pdf(std::uint32_t index, const Vec3& from, const Vec3& on_light, std::uint32_t group = 0) const;

  // The probability that sample() at `point` picks light `index` (render.light_sampler).
  float pick_probability(std::uint32_t index, const Vec3& point, std::uint32_t group = 0) const;

  // The environment, or null; and the pdf sample() has of reaching it along `direction` (solid
  // angle, pick probability included).
  const EnvironmentLight* environment() const { return environment_; }
  float environment_pdf(const Vec3& direction, std::uint32_t group = 0) const;
  // The same for the direction at `uv` in the environment's image (EnvironmentLight::image_coordinates).
  float environment_pdf_at(EnvironmentLight::ImageCoordinates uv, std::uint32_t group = 0) const;
  std::uint32_t environment_index() const { return environment_index_; }

  // The nearest light without geometry (sphere and rectangle lights) illuminating the group that
  // `ray` sees before t_max, with its index and the radiance it shows. The others are not there
  // for the group's rays.
  struct SeenLight {
    std::uint32_t index;
    float t;
    Color radiance;
  };
  // Inline up to the common case, a scene without sphere or rectangle lights: every path vertex asks.
  std::optional<SeenLight> seen_light(const Ray& ray, float t_max, std::uint32_t group = 0) const {
    if (linked(group).analytic.empty()) return std::nullopt;
    return nearest_analytic_light(ray, t_max, group);
  }

 private:
  // What a distinct set of illuminating lights picks from, and its sphere and rectangle lights.
  struct Linked {
    LightPicker picker;
    std::vector<std::uint32_t> analytic;
  };
  const Linked& linked(std::uint32_t group) const { return linked_[linked_of_group_[group]]; }
  const LightPicker& picker(std::uint32_t group) const { return linked(group).picker; }
  std::optional<SeenLight> nearest_analytic_light(const Ray& ray, float t_max, std::uint32_t group) const;

  std::vector<PathLight> lights_;
  std::vector<Linked> linked_;                  // [0]: every light
  std::vector<std::uint32_t> linked_of_group_;  // per link group (one without linking)
  const EnvironmentLight* environment_ = nullptr;
  std::uint32_t environment_index_ = kInvalidId;
  // Per emitting geometry, keyed by (instance, geometry) as a hit names them: the light index of
  // each primitive (kInvalidId where it does not emit).
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> light_of_primitive_;

  void add_emitters(const RenderScene& scene, const Group& group, std::uint32_t instance, const Affine* to_world);
  void link(const RenderScene& scene, std::span<const float> power, std::span<const std::optional<LightBounds>> bounds);
};

}  // namespace rtpro
