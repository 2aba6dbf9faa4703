#include "light_set.h"

#include "point_light_batch.h"
#include "rtpro/core/error.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>

namespace rtpro {

LightSet::LightSet(const RenderScene& scene, const EnvironmentLight* environment) : environment_(environment) {
  if (scene.environment && !environment)
    throw std::logic_error("LightSet: the scene has an environment but none was built for it");
  if (environment && environment->sampling() == EnvironmentSampling::kAboveMean &&
      environment_sampling_for(scene.render) != EnvironmentSampling::kAboveMean)
    throw std::logic_error("LightSet: an environment sampled above its mean needs MIS with BSDF samples");
  const LightUnits units = scene.render.light_units.value_or(LightUnits::kRadiometric);
  for (const Light& light : scene.lights) lights_.push_back(path_light_of(light, units));
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
    const float p = path_light_power(light, scene_radius);
    power.push_back(std::isfinite(p) && p > 0.0f ? p : 0.0f);
  }
  std::vector<std::optional<LightBounds>> light_bounds;
  light_bounds.reserve(lights_.size());
  for (std::uint32_t i = 0; i < lights_.size(); ++i) light_bounds.push_back(path_light_bounds(lights_[i], power[i]));
  link(scene, power, light_bounds);
}

// One picker per distinct set of lights that illuminate a link group: every light but the scene
// lights the group is not linked to, in the set's order. Groups lit alike are found by hashing
// their flags (comparing each group with every earlier one was cubic in the scene's size), and the
// pickers' total size is checked before any is built: each holds a tree over all its lights, so
// 3,000 sets of "every light but one" among 3,000 lights asked for 9 million entries and 2.2 GB
// (about 250 bytes an entry: the limit, 2^21 entries, is about 500 MB).
void LightSet::link(const RenderScene& scene, std::span<const float> power,
                    std::span<const std::optional<LightBounds>> bounds) {
  const std::vector<LinkGroup>& groups = scene.links.groups;
  linked_of_group_.assign(std::max<std::size_t>(groups.size(), 1), 0);
  std::unordered_map<std::string_view, std::uint32_t> set_of_flags;
  std::vector<std::uint32_t> first_group_of_set;
  std::uint64_t entries = 0;
  const std::size_t unlinked = lights_.size() - scene.lights.size();  // emitters and the environment
  for (std::uint32_t g = 0; g < linked_of_group_.size(); ++g) {
    const std::string_view flags =
        groups.empty() ? std::string_view()
                       : std::string_view(reinterpret_cast<const char*>(groups[g].illuminated_by.data()),
                                          groups[g].illuminated_by.size());
    const auto [set, added] = set_of_flags.try_emplace(flags, static_cast<std::uint32_t>(first_group_of_set.size()));
    linked_of_group_[g] = set->second;
    if (!added) continue;
    first_group_of_set.push_back(g);
    entries += unlinked + static_cast<std::uint64_t>(std::count(flags.begin(), flags.end(), 1));
  }
  if (entries > kMaxLinkedLightEntries)
    throw InputError("light linking: " + std::to_string(first_group_of_set.size()) +
                     " distinct sets of illuminating lights sample " + std::to_string(entries) +
                     " lights in all (each set a light tree of its own over its scene lights and the " +
                     std::to_string(unlinked) + " emissive surfaces and environment), more than the limit of " +
                     std::to_string(kMaxLinkedLightEntries) +
                     "; give objects fewer distinct sets of lights (link an instance of many objects once)");
  for (const std::uint32_t g : first_group_of_set) {
    std::vector<std::uint32_t> members;
    Linked linked;
    for (std::uint32_t i = 0; i < lights_.size(); ++i) {
      if (i < scene.lights.size() && !scene.links.illuminates(g, i)) continue;
      members.push_back(i);
      if (met_by_rays(lights_[i])) linked.analytic.push_back(i);
    }
    linked.picker = LightPicker(scene.render.light_sampler, members, power, bounds);
    linked_.push_back(std::move(linked));
  }
}

float LightSet::pick_probability(std::uint32_t index, const Vec3& point, std::uint32_t group) const {
  return picker(group).probability(index, point);
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
        if (!scale) break;  // ellipsoids: see render/lights/light_set.h
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
            if (mesh.uvs.empty()) light.uv = {TexCoord{0.0f, 0.0f}, TexCoord{1.0f, 0.0f}, TexCoord{0.0f, 1.0f}};
            else light.uv = {mesh.uvs[tri.v0], mesh.uvs[tri.v1], mesh.uvs[tri.v2]};
          }
          add(t, count, light);
        }
        break;
      }
      case GeometryKind::kInstance: break;  // the top level's instances are visited by the constructor
      case GeometryKind::kCurves: break;    // never emit: the scene builder refuses emitting curves
    }
  }
}

std::optional<LightSet::LonePointLight> LightSet::lone_point_light() const {
  if (linked_.size() != 1 || linked_.front().picker.empty() || linked_.front().picker.picks_by_number())
    return std::nullopt;
  LightPicker::Pick pick;
  // A picker that reads no number picks the same light from every point.
  if (!linked_.front().picker.pick(Vec3(0.0f), 0.0f, pick)) return std::nullopt;
  const auto* point = std::get_if<PointLight>(&lights_[pick.light]);
  if (point == nullptr) return std::nullopt;
  return LonePointLight{point, pick.light, pick.pmf};
}

void LightSet::sample_lone_point_light(const LonePointLight& lone, std::span<const SurfacePoint> points,
                                       std::span<PathLightSample> out, std::span<std::uint8_t> found) {
  sample_point_light_batch(*lone.light, points, out, found);
  // LightSet::sample's own finishing touches to a point light's sample.
  for (std::size_t i = 0; i < points.size(); ++i) {
    out[i].pdf *= lone.pmf;
    out[i].light = lone.index;
  }
}

bool LightSet::reads_pick_number() const {
  return std::any_of(linked_.begin(), linked_.end(), [](const Linked& l) { return l.picker.picks_by_number(); });
}

bool LightSet::reads_point_numbers() const { return std::any_of(lights_.begin(), lights_.end(), samples_by_number); }

std::uint32_t LightSet::light_of_hit(const Hit& hit) const {
  const auto found = light_of_primitive_.find(geometry_key(hit.inst_id, hit.geom_id));
  return found == light_of_primitive_.end() || hit.prim_id >= found->second.size() ? kInvalidId
                                                                                   : found->second[hit.prim_id];
}

float LightSet::pdf(std::uint32_t index, const Vec3& from, const Vec3& on_light, std::uint32_t group) const {
  if (index >= lights_.size() || empty(group)) return 0.0f;
  return pick_probability(index, from, group) * path_light_pdf(lights_[index], from, on_light);
}

float LightSet::environment_pdf(const Vec3& direction, std::uint32_t group) const {
  return environment_ ? environment_pdf_at(environment_->image_coordinates(direction), group) : 0.0f;
}

float LightSet::environment_pdf_at(EnvironmentLight::ImageCoordinates uv, std::uint32_t group) const {
  if (environment_index_ == kInvalidId || empty(group)) return 0.0f;
  return pick_probability(environment_index_, Vec3(0.0f), group) * environment_->pdf_at(uv);
}

std::optional<LightSet::SeenLight> LightSet::nearest_analytic_light(const Ray& ray, float t_max,
                                                                    std::uint32_t group) const {
  std::optional<SeenLight> nearest;
  for (const std::uint32_t index : linked(group).analytic) {
    Color radiance;
    const float t = meet_path_light(lights_[index], ray, t_max, radiance);
    if (t < t_max) {
      nearest = SeenLight{index, t, radiance};
      t_max = t;
    }
  }
  return nearest;
}

}  // namespace rtpro
