#include "rtpro/render/light_set.h"

#include "sphere_sampling.h"
#include "rtpro/core/math_constants.h"
#include "rtpro/render/light_sample.h"
#include "rtpro/render/shading_frame.h"
#include "rtpro/render/texture.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <stdexcept>

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
  static BBox sphere_box(const Vec3& center, float radius) { return box({center - Vec3(radius), center + Vec3(radius)}); }
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
    return LightBounds{box({l.corner, l.corner + l.edge1, l.corner + l.edge2, l.corner + l.edge1 + l.edge2}), l.normal,
                       power, 1.0f, 0.0f, false};
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

  bool found(const Vec3& direction, float distance, const Color& radiance, float pdf, bool delta) const {
    out.direction = direction;
    out.distance = distance;
    out.radiance = radiance;
    out.pdf = pdf;
    out.delta = delta;
    return true;
  }

  bool operator()(const PointLight& l) const {
    const Vec3 to_light = l.position - from;
    const float d2 = dot(to_light, to_light);
    if (!(d2 > 0.0f)) return false;
    const float d = std::sqrt(d2);
    return found(to_light / d, d, l.radiance / d2, 1.0f, true);
  }
  bool operator()(const SpotLight& l) const {
    const Vec3 to_light = l.position - from;
    const float d2 = dot(to_light, to_light);
    if (!(d2 > 0.0f)) return false;
    const float d = std::sqrt(d2);
    const Vec3 direction = to_light / d;
    const float falloff = l.falloff(-direction);
    if (!(falloff > 0.0f)) return false;  // outside the outer cone
    return found(direction, d, l.radiance * (falloff / d2), 1.0f, true);
  }
  bool operator()(const DirectionalLight& l) const {
    return found(l.to_light, kInfinity, l.radiance, 1.0f, true);
  }
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
    return on_surface({point, l.normal, area_to_solid_angle(1.0f / l.area, from, point, l.normal)}, l.emission,
                      tex_u, tex_v);
  }
  bool operator()(const EmissiveSphere& l) const {
    const SphereSample s = sample_sphere(l.center, l.radius, from, u);
    const TexCoord uv = sphere_texture_coordinates(s.normal);
    return on_surface(s, l.emission, uv.u, uv.v);
  }
  bool operator()(const EnvironmentRef& l) const {
    const std::optional<EnvironmentLight::Sample> s = l.light->sample(u);
    if (!s || s->radiance == Color(0.0f)) return false;
    return found(s->direction, kInfinity, s->radiance, s->pdf, false);
  }

  bool on_surface(const SphereSample& s, const Emission& emission, float tex_u = 0.0f, float tex_v = 0.0f) const {
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

// Where `ray` meets one of those before t_max (`seen`: the radiance it shows there).
struct Meeting {
  const Ray& ray;
  float t_max;
  Color& seen;
  std::optional<float> operator()(const PointLight&) const { return std::nullopt; }
  std::optional<float> operator()(const SpotLight&) const { return std::nullopt; }
  std::optional<float> operator()(const DirectionalLight&) const { return std::nullopt; }
  std::optional<float> operator()(const SphereLight& l) const {
    if (!clearly_outside(l.center, l.radius, ray.org)) return std::nullopt;  // no light inside
    seen = l.radiance;
    return hit_light(Light(l), ray, t_max);
  }
  std::optional<float> operator()(const QuadLight& l) const {
    seen = l.radiance;
    return hit_light(Light(l), ray, t_max);
  }
  std::optional<float> operator()(const EmissiveTriangle&) const { return std::nullopt; }
  std::optional<float> operator()(const EmissiveSphere&) const { return std::nullopt; }
  std::optional<float> operator()(const EnvironmentRef&) const { return std::nullopt; }
};

}  // namespace

LightSet::LightSet(const RenderScene& scene, const EnvironmentLight* environment) : environment_(environment) {
  if (scene.environment && !environment)
    throw std::logic_error("LightSet: the scene has an environment but none was built for it");
  for (const Light& light : scene.lights) std::visit([&](const auto& l) { lights_.push_back(l); }, light);
  add_emitters(scene, scene.top, kInvalidId, nullptr);
  for (std::uint32_t g = 0; g < scene.top.geometries.size(); ++g)
    if (const auto* instance = std::get_if<Instance>(&scene.top.geometries[g]))
      add_emitters(scene, scene.prototypes[instance->prototype], g, &instance->object_to_world);
  if (environment_) {
    environment_index_ = static_cast<std::uint32_t>(lights_.size());
    lights_.push_back(EnvironmentRef{environment_});
  }
  const BBox bounds = scene.bounds();
  const float scene_radius = bounds.empty() ? 1.0f : 0.5f * length(bounds.upper - bounds.lower);
  std::vector<float> power;
  power.reserve(lights_.size());
  for (const PathLight& light : lights_) {
    const float p = std::visit(Power{scene_radius}, light);
    power.push_back(std::isfinite(p) && p > 0.0f ? p : 0.0f);
  }
  std::vector<std::optional<LightBounds>> light_bounds;
  light_bounds.reserve(lights_.size());
  for (std::uint32_t i = 0; i < lights_.size(); ++i) light_bounds.push_back(std::visit(Bounds{power[i]}, lights_[i]));
  link(scene, power, light_bounds);
}

// One picker per distinct set of lights that illuminate a link group: every light but the scene
// lights the group is not linked to, in the set's order.
void LightSet::link(const RenderScene& scene, std::span<const float> power,
                    std::span<const std::optional<LightBounds>> bounds) {
  const std::vector<LinkGroup>& groups = scene.links.groups;
  linked_of_group_.assign(std::max<std::size_t>(groups.size(), 1), 0);
  for (std::uint32_t g = 0; g < linked_of_group_.size(); ++g) {
    std::uint32_t same = 0;
    while (same < g && groups[same].illuminated_by != groups[g].illuminated_by) ++same;
    if (same < g) {
      linked_of_group_[g] = linked_of_group_[same];
      continue;
    }
    std::vector<std::uint32_t> members;
    Linked linked;
    for (std::uint32_t i = 0; i < lights_.size(); ++i) {
      if (i < scene.lights.size() && !scene.links.illuminates(g, i)) continue;
      members.push_back(i);
      if (std::visit(MetByRays{}, lights_[i])) linked.analytic.push_back(i);
    }
    linked.picker = LightPicker(scene.render.light_sampler, members, power, bounds);
    linked_of_group_[g] = static_cast<std::uint32_t>(linked_.size());
    linked_.push_back(std::move(linked));
  }
}

float LightSet::pick_probability(std::uint32_t index, const Vec3& point, std::uint32_t group) const {
  return picker(group).probability(index, point);
}

bool LightSet::sample(const Vec3& point, float u_pick, Sample2D u, const TextureLookup* textures, std::uint32_t group,
                      PathLightSample& out) const {
  const std::optional<LightPicker::Pick> pick = picker(group).pick(point, u_pick);
  if (!pick) return false;
  if (!std::visit(Sampler{point, u, textures, out}, lights_[pick->light])) return false;
  out.pdf *= pick->pmf;
  out.light = pick->light;
  return true;
}

namespace {

std::uint64_t geometry_key(std::uint32_t instance, std::uint32_t geometry) {
  return static_cast<std::uint64_t>(instance) << 32 | geometry;
}

// The factor a transform scales every length by, or nothing when it scales directions unequally.
std::optional<float> uniform_scale(const Affine& m) {
  const float x = length(m.apply_vector(Vec3(1.0f, 0.0f, 0.0f)));
  const float y = length(m.apply_vector(Vec3(0.0f, 1.0f, 0.0f)));
  const float z = length(m.apply_vector(Vec3(0.0f, 0.0f, 1.0f)));
  const float tolerance = 1e-5f * std::max({x, y, z});
  if (std::fabs(x - y) > tolerance || std::fabs(x - z) > tolerance) return std::nullopt;
  return x;
}

}  // namespace

// The emitting spheres and triangles of `group`, in world space through `to_world` (null: the top
// level, already in world space). `instance` is the top-level geometry id hits report for them.
void LightSet::add_emitters(const RenderScene& scene, const Group& group, std::uint32_t instance,
                            const Affine* to_world) {
  const auto world_point = [&](const Vec3& p) { return to_world ? to_world->apply_point(p) : p; };
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) {
    const Geometry& geometry = group.geometries[g];
    std::vector<std::uint32_t>* of_primitive = nullptr;
    const auto add = [&](std::uint32_t prim, std::size_t count, PathLight light) {
      if (!of_primitive) {
        of_primitive = &light_of_primitive_[geometry_key(instance, g)];
        of_primitive->assign(count, kInvalidId);
      }
      (*of_primitive)[prim] = static_cast<std::uint32_t>(lights_.size());
      lights_.push_back(light);
    };
    switch (kind_of(geometry)) {
      case GeometryKind::kSpheres: {
        const auto& spheres = std::get<SphereSet>(geometry).spheres;
        const std::optional<float> scale = to_world ? uniform_scale(*to_world) : std::optional<float>(1.0f);
        if (!scale) break;  // ellipsoids: see the header
        for (std::uint32_t i = 0; i < spheres.size(); ++i) {
          const Emission& e = scene.materials[spheres[i].material].emission;
          const float radius = spheres[i].radius * *scale;
          if (e.emits() && radius > 0.0f && std::isfinite(radius) && !(e.texture && to_world))
            add(i, spheres.size(), EmissiveSphere{world_point(spheres[i].center), radius, e});
        }
        break;
      }
      case GeometryKind::kTriangles: {
        const TriangleMesh& mesh = std::get<TriangleMesh>(geometry);
        const auto count = static_cast<std::uint32_t>(mesh.triangle_count());
        for (std::uint32_t t = 0; t < count; ++t) {
          const Emission& e = scene.materials[mesh.material_of(t)].emission;
          if (!e.emits()) continue;
          const TriangleIndices& tri = mesh.triangles[t];
          const Vec3 p0 = world_point(mesh.vertex(tri.v0));
          const Vec3 e1 = world_point(mesh.vertex(tri.v1)) - p0, e2 = world_point(mesh.vertex(tri.v2)) - p0;
          const Vec3 n = cross(e1, e2);
          const float twice_area = length(n);
          if (!(twice_area > 0.0f) || !std::isfinite(twice_area)) continue;  // degenerate: hit only by BSDF samples
          // A mirroring transform turns the winding: the front stays where the surface's own
          // normal, carried along, points (as make_surface sees it).
          const bool mirrored = to_world && dot(cross(to_world->apply_vector(Vec3(1.0f, 0.0f, 0.0f)),
                                                      to_world->apply_vector(Vec3(0.0f, 1.0f, 0.0f))),
                                                to_world->apply_vector(Vec3(0.0f, 0.0f, 1.0f))) < 0.0f;
          EmissiveTriangle light{p0, e1, e2, n / (mirrored ? -twice_area : twice_area), 0.5f * twice_area, e};
          if (e.texture) {
            if (mesh.uvs.empty())
              light.uv = {TexCoord{0.0f, 0.0f}, TexCoord{1.0f, 0.0f}, TexCoord{0.0f, 1.0f}};
            else
              light.uv = {mesh.uvs[tri.v0], mesh.uvs[tri.v1], mesh.uvs[tri.v2]};
          }
          add(t, count, light);
        }
        break;
      }
      case GeometryKind::kInstance: break;  // the top level's instances are visited by the constructor
    }
  }
}

std::uint32_t LightSet::light_of_hit(const Hit& hit) const {
  const auto found = light_of_primitive_.find(geometry_key(hit.inst_id, hit.geom_id));
  return found == light_of_primitive_.end() || hit.prim_id >= found->second.size() ? kInvalidId
                                                                                   : found->second[hit.prim_id];
}

float LightSet::pdf(std::uint32_t index, const Vec3& from, const Vec3& on_light, std::uint32_t group) const {
  if (index >= lights_.size() || empty(group)) return 0.0f;
  return pick_probability(index, from, group) * std::visit(Pdf{from, on_light}, lights_[index]);
}

float LightSet::environment_pdf(const Vec3& direction, std::uint32_t group) const {
  if (environment_index_ == kInvalidId || empty(group)) return 0.0f;
  return pick_probability(environment_index_, Vec3(0.0f), group) * environment_->pdf(direction);
}

std::optional<LightSet::SeenLight> LightSet::nearest_analytic_light(const Ray& ray, float t_max,
                                                                    std::uint32_t group) const {
  std::optional<SeenLight> nearest;
  for (const std::uint32_t index : linked(group).analytic) {
    Color radiance;
    const std::optional<float> t = std::visit(Meeting{ray, nearest ? nearest->t : t_max, radiance}, lights_[index]);
    if (t) nearest = SeenLight{index, *t, radiance};
  }
  return nearest;
}

}  // namespace rtpro
