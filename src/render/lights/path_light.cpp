#include "path_light.h"

#include "sphere_sampling.h"
#include "rtpro/core/math_constants.h"
#include "light_sample.h"
#include "shading_frame.h"
#include "texture.h"

#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>
#include <variant>

namespace rtpro {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float average(const Color& c) { return (c.x + c.y + c.z) * (1.0f / 3.0f); }

// What the pick distribution weighs each light by: the power it emits (the average of its
// channels). A directional light delivers its irradiance over the disk the scene fills.
struct Power {
  float scene_radius;
  float operator()(const PointLight& l) const { return 4.0f * kPi * average(l.radiance); }
  // pbrt-v4's: the inner cone at full intensity, the falloff band counted at half.
  float operator()(const SpotLight& l) const {
    return 2.0f * kPi * average(l.radiance) * ((1.0f - l.cos_inner) + (l.cos_inner - l.cos_outer) * 0.5f);
  }
  float operator()(const DirectionalLight& l) const { return kPi * scene_radius * scene_radius * average(l.radiance); }
  float operator()(const SphereLight& l) const { return kPi * 4.0f * kPi * l.radius * l.radius * average(l.radiance); }
  float operator()(const QuadLight& l) const { return kPi * l.area * average(l.radiance); }
  float operator()(const EmissiveTriangle& l) const {
    return kPi * l.area * average(l.emission.radiance) * (l.emission.two_sided ? 2.0f : 1.0f);
  }
  float operator()(const EmissiveSphere& l) const {
    return kPi * 4.0f * kPi * l.radius * l.radius * average(l.emission.radiance) * (l.emission.two_sided ? 2.0f : 1.0f);
  }
  // Its radiance from the whole sphere of directions through the disk the scene fills.
  float operator()(const EnvironmentRef& l) const {
    return kPi * scene_radius * scene_radius * 4.0f * kPi * l.light->mean_radiance();
  }
};

// Where each light is and which way it shines, for the light tree; nothing for the lights
// without a position. `power` is what Power gives it.
struct Bounds {
  float power;
  static BBox box(std::initializer_list<Vec3> points) {
    BBox b;
    for (const Vec3& p : points) b.extend(p);
    return b;
  }
  static BBox sphere_box(const Vec3& center, float radius) {
    return box({center - Vec3(radius), center + Vec3(radius)});
  }
  // A point light shines every way: a sphere of normals (cos θ_o = −1), each emitting over its
  // hemisphere (θ_e = π/2), as pbrt-v4 bounds it.
  std::optional<LightBounds> operator()(const PointLight& l) const {
    return LightBounds{box({l.position}), Vec3(0, 0, 1), power, -1.0f, 0.0f, false};
  }
  // A spot light: its directions within the outer cone (θ_o), and no further (θ_e just above 0:
  // the importance is zero only strictly outside, so the cone's edge is never ruled out). Its
  // power as a point light's of the same intensity, as pbrt-v4 has it: the bounds already account
  // for the cone, and two spots of equal intensity should be equally likely where both reach.
  std::optional<LightBounds> operator()(const SpotLight& l) const {
    return LightBounds{box({l.position}), l.axis, 4.0f * kPi * average(l.radiance), l.cos_outer, 0.999f, false};
  }
  std::optional<LightBounds> operator()(const DirectionalLight&) const { return std::nullopt; }
  std::optional<LightBounds> operator()(const SphereLight& l) const {
    return LightBounds{sphere_box(l.center, l.radius), Vec3(0, 0, 1), power, -1.0f, 0.0f, false};
  }
  std::optional<LightBounds> operator()(const QuadLight& l) const {
    return LightBounds{box({l.corner, l.corner + l.edge1, l.corner + l.edge2, l.corner + l.edge1 + l.edge2}),
                       l.normal,
                       power,
                       1.0f,
                       0.0f,
                       false};
  }
  std::optional<LightBounds> operator()(const EmissiveTriangle& l) const {
    return LightBounds{box({l.p0, l.p0 + l.e1, l.p0 + l.e2}), l.normal, power, 1.0f, 0.0f, l.emission.two_sided};
  }
  std::optional<LightBounds> operator()(const EmissiveSphere& l) const {
    return LightBounds{sphere_box(l.center, l.radius), Vec3(0, 0, 1), power, -1.0f, 0.0f, l.emission.two_sided};
  }
  std::optional<LightBounds> operator()(const EnvironmentRef&) const { return std::nullopt; }
};

// What an emitter with normal `n` sends along `direction` (from the point towards the emitter).
Color emitted_towards(const Emission& e, const Vec3& n, const Vec3& direction) {
  const float facing = -dot(n, direction);
  return (facing > 0.0f || (e.two_sided && facing < 0.0f)) ? e.radiance : Color(0.0f);
}

// Each kind writes its sample into `out` field by field and says whether there is one: a sample
// returned as a record was copied with wide loads over the narrow stores that built it (a
// store-forwarding stall per light sample).
struct Sampler {
  const Vec3& from;
  Sample2D u;
  const TextureLookup* textures;
  PathLightSample& out;
  EnvironmentRadiance environment_radiance;

  bool found(const Vec3& direction, float distance, const Color& radiance, float pdf, bool delta) const {
    out.direction = direction;
    out.distance = distance;
    out.radiance = radiance;
    out.pdf = pdf;
    out.delta = delta;
    out.environment = nullptr;
    return true;
  }

  bool operator()(const PointLight& l) const { return sample_point_light(l, from, out); }
  bool operator()(const SpotLight& l) const {
    const Vec3 to_light = l.position - from;
    const float d2 = dot(to_light, to_light);
    if (!(d2 > 0.0f)) return false;
    const float d = std::sqrt(d2);
    const Vec3 direction = to_light / d;
    const float falloff = l.falloff(-direction);
    if (!(falloff > 0.0f)) return false;  // outside the outer cone
    return found(direction, d, l.radiance * (l.inverse_square ? falloff / d2 : falloff), 1.0f, true);
  }
  bool operator()(const DirectionalLight& l) const { return found(l.to_light, kInfinity, l.radiance, 1.0f, true); }
  bool operator()(const SphereLight& l) const {
    if (!clearly_outside(l.center, l.radius, from)) return false;  // emits outwards only
    return on_surface(sample_sphere(l.center, l.radius, from, u), Emission{l.radiance, false, std::nullopt});
  }
  bool operator()(const QuadLight& l) const {
    const Vec3 point = l.corner + l.edge1 * u.x + l.edge2 * u.y;
    return on_surface({point, l.normal, area_to_solid_angle(1.0f / l.area, from, point, l.normal)},
                      Emission{l.radiance, false, std::nullopt});
  }
  bool operator()(const EmissiveTriangle& l) const {
    // Uniform over the triangle (the square folded onto it).
    float b1 = u.x, b2 = u.y;
    if (b1 + b2 > 1.0f) {
      b1 = 1.0f - b1;
      b2 = 1.0f - b2;
    }
    const Vec3 point = l.p0 + l.e1 * b1 + l.e2 * b2;
    // The texture coordinates make_surface interpolates at the same barycentrics.
    const float b0 = 1.0f - b1 - b2;
    const float tex_u = l.uv[0].u * b0 + l.uv[1].u * b1 + l.uv[2].u * b2;
    const float tex_v = l.uv[0].v * b0 + l.uv[1].v * b1 + l.uv[2].v * b2;
    return on_surface({point, l.normal, area_to_solid_angle(1.0f / l.area, from, point, l.normal)}, l.emission, tex_u,
                      tex_v);
  }
  bool operator()(const EmissiveSphere& l) const {
    const SphereSample s = sample_sphere(l.center, l.radius, from, u);
    const TexCoord uv = sphere_texture_coordinates(s.normal);
    return on_surface(s, l.emission, uv.u, uv.v);
  }
  bool operator()(const EnvironmentRef& l) const {
    if (environment_radiance == EnvironmentRadiance::kLater) {
      const std::optional<Vec3> direction = l.light->sample_direction(u);
      if (!direction) return false;
      found(*direction, kInfinity, Color(0.0f), 1.0f, false);  // the pick's pmf multiplies the 1
      out.environment = l.light;
      return true;
    }
    const std::optional<EnvironmentLight::Sample> s = l.light->sample(u);
    if (!s || s->radiance == Color(0.0f)) return false;
    return found(s->direction, kInfinity, s->radiance, s->pdf, false);
  }

  [[gnu::always_inline]] bool on_surface(const SphereSample& s, const Emission& emission, float tex_u = 0.0f,
                                         float tex_v = 0.0f) const {
    const Vec3 to_light = s.point - from;
    const float d = length(to_light);
    if (!(d > 0.0f) || !(s.pdf > 0.0f) || !std::isfinite(s.pdf)) return false;
    const Vec3 direction = to_light / d;
    Color radiance = emitted_towards(emission, s.normal, direction);
    if (emission.texture && radiance != Color(0.0f))
      radiance = radiance * evaluate(*emission.texture, tex_u, tex_v, textures);
    if (radiance == Color(0.0f)) return false;
    return found(direction, d, radiance, s.pdf, false);
  }
};

struct Pdf {
  const Vec3& from;
  const Vec3& on_light;
  float operator()(const PointLight&) const { return 0.0f; }
  float operator()(const SpotLight&) const { return 0.0f; }
  float operator()(const DirectionalLight&) const { return 0.0f; }
  float operator()(const SphereLight& l) const {
    return clearly_outside(l.center, l.radius, from) ? sphere_pdf(l.center, l.radius, from, on_light) : 0.0f;
  }
  float operator()(const QuadLight& l) const { return area_to_solid_angle(1.0f / l.area, from, on_light, l.normal); }
  float operator()(const EmissiveTriangle& l) const {
    return area_to_solid_angle(1.0f / l.area, from, on_light, l.normal);
  }
  float operator()(const EmissiveSphere& l) const { return sphere_pdf(l.center, l.radius, from, on_light); }
  // `on_light`: any point along the direction (the environment is infinitely far).
  float operator()(const EnvironmentRef& l) const { return l.light->pdf(on_light - from); }
};

// The lights without geometry that camera and BSDF rays can meet (sphere and quad lights): the
// backend finds the emissive surfaces, and no ray meets a point, spot or directional light.
struct MetByRays {
  bool operator()(const PointLight&) const { return false; }
  bool operator()(const SpotLight&) const { return false; }
  bool operator()(const DirectionalLight&) const { return false; }
  bool operator()(const SphereLight&) const { return true; }
  bool operator()(const QuadLight&) const { return true; }
  bool operator()(const EmissiveTriangle&) const { return false; }
  bool operator()(const EmissiveSphere&) const { return false; }
  bool operator()(const EnvironmentRef&) const { return false; }
};

// The lights whose sample is a point chosen by the sample's numbers.
struct SamplesByNumber {
  bool operator()(const PointLight&) const { return false; }
  bool operator()(const SpotLight&) const { return false; }
  bool operator()(const DirectionalLight&) const { return false; }
  bool operator()(const SphereLight&) const { return true; }
  bool operator()(const QuadLight&) const { return true; }
  bool operator()(const EmissiveTriangle&) const { return true; }
  bool operator()(const EmissiveSphere&) const { return true; }
  bool operator()(const EnvironmentRef&) const { return true; }
};

// Where `ray` meets one of those before t_max (`seen`: the radiance it shows there).
struct Meeting {
  const Ray& ray;
  float t_max;
  Color& seen;
  float operator()(const PointLight&) const { return kLightMissed; }
  float operator()(const SpotLight&) const { return kLightMissed; }
  float operator()(const DirectionalLight&) const { return kLightMissed; }
  float operator()(const SphereLight& l) const {
    if (!clearly_outside(l.center, l.radius, ray.org)) return kLightMissed;  // no light inside
    seen = l.radiance;
    return hit_light_of_kind(l, ray, t_max);
  }
  float operator()(const QuadLight& l) const {
    seen = l.radiance;
    return hit_light_of_kind(l, ray, t_max);
  }
  float operator()(const EmissiveTriangle&) const { return kLightMissed; }
  float operator()(const EmissiveSphere&) const { return kLightMissed; }
  float operator()(const EnvironmentRef&) const { return kLightMissed; }
};

// Each visitor above has an overload for every kind of PathLight: a kind without one stops the
// build here, the kind and the visitor named, rather than deep inside std::visit.
template <typename Kind>
constexpr bool has_path_light_overloads() {
  static_assert(std::is_invocable_v<const Power&, const Kind&>,
                "a kind of light needs its Power: what it is picked by");
  static_assert(std::is_invocable_v<const Bounds&, const Kind&>,
                "a kind of light needs its Bounds: its box and cone in the light tree, or nothing");
  static_assert(std::is_invocable_v<const Sampler&, const Kind&>,
                "a kind of light needs its Sampler: a sample of it seen from a point");
  static_assert(std::is_invocable_v<const Pdf&, const Kind&>, "a kind of light needs its Pdf: that sample's pdf");
  static_assert(std::is_invocable_v<const MetByRays&, const Kind&>,
                "a kind of light needs its MetByRays: whether camera and BSDF rays meet it here");
  static_assert(std::is_invocable_v<const SamplesByNumber&, const Kind&>,
                "a kind of light needs its SamplesByNumber: whether its sample is a point the numbers choose");
  static_assert(std::is_invocable_v<const Meeting&, const Kind&>,
                "a kind of light needs its Meeting: where a ray meets it, for one MetByRays says rays meet");
  return true;
}

template <typename... Kinds>
constexpr bool has_path_light_overloads(const std::variant<Kinds...>*) {
  return (has_path_light_overloads<Kinds>() && ...);
}
static_assert(has_path_light_overloads(static_cast<const PathLight*>(nullptr)));

}  // namespace

PathLight path_light_of(const Light& light, LightUnits units) {
  return std::visit(
      [units](auto l) -> PathLight {
        if (units == LightUnits::kRadiometric) return l;
        // What the whitted integrator shows as colour × irradiance, Lambert shows as colour ×
        // irradiance / π: the same image takes π times the light.
        l.radiance = l.radiance * kPi;
        if constexpr (requires { l.inverse_square; }) l.inverse_square = false;
        return l;
      },
      light);
}

float path_light_power(const PathLight& light, float scene_radius) { return std::visit(Power{scene_radius}, light); }

std::optional<LightBounds> path_light_bounds(const PathLight& light, float power) {
  return std::visit(Bounds{power}, light);
}

bool sample_path_light_of_any_kind(const PathLight& light, const Vec3& from, Sample2D u, const TextureLookup* textures,
                                   PathLightSample& out, EnvironmentRadiance environment) {
  return std::visit(Sampler{from, u, textures, out, environment}, light);
}

float path_light_pdf(const PathLight& light, const Vec3& from, const Vec3& on_light) {
  return std::visit(Pdf{from, on_light}, light);
}

bool met_by_rays(const PathLight& light) { return std::visit(MetByRays{}, light); }

bool samples_by_number(const PathLight& light) { return std::visit(SamplesByNumber{}, light); }

float meet_path_light(const PathLight& light, const Ray& ray, float t_max, Color& seen) {
  return std::visit(Meeting{ray, t_max, seen}, light);
}

}  // namespace rtpro
