#include "embree_scene_builder.h"

#include "backend_shapes.h"
#include "rtpro/core/error.h"
#include "rtpro/core/overloaded.h"
#include "rtpro/core/ray.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <variant>

namespace rtpro {

namespace {

// Embree's commit silently drops primitives with coordinates beyond about 1.8e18 (or NaN/inf);
// rtpro refuses them instead, with the same margin is_traceable() keeps for rays.
bool in_embree_range(const Vec3& p) { return within_traceable_range(p); }

bool in_embree_range(const BBox& box) {
  return box.empty() || (in_embree_range(box.lower) && in_embree_range(box.upper));
}

std::string group_name(int group) {
  return group < 0 ? std::string("the top group") : "prototype group " + std::to_string(group);
}

[[noreturn]] void refuse(int group, std::uint32_t geometry, const std::string& problem) {
  throw RuntimeError("cannot build the Embree scene: geometry " + std::to_string(geometry) + " of " +
                     group_name(group) + " " + problem);
}

void validate_instance(const Instance& instance, std::span<const BBox> prototype_bounds, std::uint32_t geometry) {
  if (instance.prototype >= prototype_bounds.size()) refuse(-1, geometry, "instances a missing prototype");
  const BBox world = instance.object_to_world.apply(prototype_bounds[instance.prototype]);
  if (!instance.object_to_world.is_finite() || !in_embree_range(world))
    refuse(-1, geometry, "is placed outside Embree's coordinate range");
  for (const Affine& step : instance.object_to_world_steps)
    if (!step.is_finite() || !in_embree_range(step.apply(prototype_bounds[instance.prototype])))
      refuse(-1, geometry, "moves outside Embree's coordinate range");
}

void validate_group(const Group& group, int group_index, std::span<const BBox> prototype_bounds) {
  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) {
    const Geometry& geometry = group.geometries[g];
    std::visit(Overloaded{[&](const Instance& instance) {
                            if (group_index >= 0)
                              refuse(group_index, g, "is an instance inside a prototype (one level only)");
                            validate_instance(instance, prototype_bounds, g);
                          },
                          [&](const auto& shapes) {
                            if (const std::optional<std::string> problem = embree_refusal(shapes))
                              refuse(group_index, g, *problem);
                          }},
               geometry);
  }
}

EmbreeGeometry new_instance_geometry(RTCDevice device, const Instance& instance, RTCScene prototype) {
  static_assert(sizeof(instance.object_to_world.m) == 12 * sizeof(float));
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE));
  if (!geometry) return geometry;
  RTCGeometry g = geometry.get();
  rtcSetGeometryInstancedScene(g, prototype);
  // Affine::m is row-major 3×4 (linear part, then translation, per row): Embree's FLOAT3X4_ROW_MAJOR.
  // A moving instance gives one per time step; Embree interpolates the matrices linearly, as
  // placement_at does for the native backend.
  if (instance.moving()) {
    rtcSetGeometryTimeStepCount(g, static_cast<unsigned>(instance.object_to_world_steps.size()));
    for (unsigned step = 0; step < instance.object_to_world_steps.size(); ++step)
      rtcSetGeometryTransform(g, step, RTC_FORMAT_FLOAT3X4_ROW_MAJOR,
                              instance.object_to_world_steps[step].m.data()->data());
  } else {
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, instance.object_to_world.m.data()->data());
  }
  rtcCommitGeometry(g);
  return geometry;
}

// A set of shapes without primitives gives Embree nothing to hit; an instance is always attached.
bool is_empty(const Geometry& geometry) {
  return std::visit(Overloaded{[](const Instance&) { return false; },
                               [](const auto& shapes) { return primitive_count_of(shapes) == 0; }},
                    geometry);
}

// Whether a group holds curves and nothing else, itself or through its instances.
bool holds_only_curves(const Group& group, std::span<const Group> prototypes) {
  for (const Geometry& geometry : group.geometries) {
    const bool curves = std::visit(
        Overloaded{[&](const Instance& instance) { return holds_only_curves(prototypes[instance.prototype], {}); },
                   [](const CurveSet&) { return true; }, [](const SphereSet&) { return false; },
                   [](const TriangleMesh&) { return false; }},
        geometry);
    if (!curves) return false;
  }
  return !group.geometries.empty();
}

}  // namespace

RTCSceneFlags embree_group_flags(const Group& group, std::span<const Group> prototypes,
                                 const EmbreeBuildSettings& settings) {
  if (!holds_only_curves(group, prototypes)) return settings.flags;
  return static_cast<RTCSceneFlags>(settings.flags & ~RTC_SCENE_FLAG_ROBUST);
}

namespace {

// A mesh the scene build ordered in pieces, and big enough to be split.
bool built_in_pieces(const Geometry& geometry) {
  const auto* mesh = std::get_if<TriangleMesh>(&geometry);
  return mesh != nullptr && mesh->piece_triangles != 0 && !mesh->moving() &&
         mesh->triangle_count() > mesh->piece_triangles;
}

EmbreeScene new_scene(EmbreeDevice::Session& session, RTCSceneFlags flags, const EmbreeBuildSettings& settings,
                      const std::string& where) {
  EmbreeScene scene(rtcNewScene(session.device()));
  session.check("creation of the scene for " + where);
  rtcSetSceneFlags(scene.get(), flags);
  rtcSetSceneBuildQuality(scene.get(), settings.quality);
  return scene;
}

// Each piece of top-level mesh `g` as a committed scene of its own, appended to `scenes`.
void build_pieces(EmbreeDevice::Session& session, const TriangleMesh& mesh, std::uint32_t g,
                  const EmbreeBuildSettings& settings, EmbreeScenes& scenes) {
  const std::string where = "a piece of geometry " + std::to_string(g) + " of the top group";
  for (std::uint32_t first = 0; first < mesh.triangle_count(); first += mesh.piece_triangles) {
    const auto count =
        static_cast<std::uint32_t>(std::min<std::size_t>(mesh.piece_triangles, mesh.triangle_count() - first));
    EmbreeScene piece = new_scene(session, settings.flags, settings, where);
    const EmbreeGeometry geometry = new_embree_piece(session.device(), mesh, first, count, settings.quality);
    session.check("creation of " + where);
    rtcAttachGeometryByID(piece.get(), geometry.get(), 0);
    session.check("attaching " + where);
    rtcCommitScene(piece.get());
    session.check("the BVH build of " + where);
    scenes.pieces.push_back(std::move(piece));
    scenes.hit_ids.pieces.pieces.push_back({g, first});
  }
}

// An instance placing a piece where its mesh is: no transform, so Embree's ray in the piece is
// the ray itself (an identity matrix changes no coordinate).
EmbreeGeometry new_piece_instance(RTCDevice device, RTCScene piece) {
  static constexpr float kIdentity[12] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
  EmbreeGeometry geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE));
  if (!geometry) return geometry;
  rtcSetGeometryInstancedScene(geometry.get(), piece);
  rtcSetGeometryTransform(geometry.get(), 0, RTC_FORMAT_FLOAT3X4_ROW_MAJOR, kIdentity);
  rtcCommitGeometry(geometry.get());
  return geometry;
}

// Whether the top group's instances give their prototypes' shapes to the top scene
// (EmbreeHitIds), so that it holds no instance: each places its prototype as is, nothing else
// places that prototype (or its BVH would be built twice), the prototype is built with the top
// scene's flags (robust or not), and it holds no spheres: their callbacks break ties between
// equal distances by Embree's ids (embree_user_geometry.h), which inlining would change. All or
// none: beside a single remaining instance the top scene holds two trees that every ray walks
// (`animated_shot.gltf`'s floor inlined beside its moving box took 1.2× as long).
bool top_instances_inlined(const RenderScene& scene, const EmbreeBuildSettings& settings) {
  std::vector<std::uint32_t> placements(scene.prototypes.size(), 0);
  for (const Geometry& geometry : scene.top.geometries)
    if (const auto* instance = std::get_if<Instance>(&geometry)) ++placements[instance->prototype];
  const RTCSceneFlags top_flags = embree_group_flags(scene.top, scene.prototypes, settings);
  bool any = false;
  for (const Geometry& geometry : scene.top.geometries) {
    const auto* instance = std::get_if<Instance>(&geometry);
    if (instance == nullptr) continue;
    const Group& prototype = scene.prototypes[instance->prototype];
    const bool holds_spheres = std::ranges::any_of(
        prototype.geometries, [](const Geometry& g) { return std::holds_alternative<SphereSet>(g); });
    if (!instance->places_as_is() || placements[instance->prototype] != 1 || holds_spheres ||
        embree_group_flags(prototype, {}, settings) != top_flags)
      return false;
    any = true;
  }
  return any;
}

// `top`: the top group's pieces and inlined shapes, attached after its own geometries.
EmbreeScene build_group(EmbreeDevice::Session& session, const Group& group, int group_index,
                        std::span<const Group> prototype_groups, const std::vector<EmbreeScene>& prototypes,
                        const EmbreeBuildSettings& settings, const EmbreeScenes* top = nullptr) {
  RTCDevice device = session.device();
  const std::string where = group_name(group_index);
  EmbreeScene scene = new_scene(session, embree_group_flags(group, prototype_groups, settings), settings, where);

  for (std::uint32_t g = 0; g < group.geometries.size(); ++g) {
    const Geometry& geometry = group.geometries[g];
    if (is_empty(geometry)) continue;                           // nothing to hit; ids need not be contiguous
    if (top != nullptr && built_in_pieces(geometry)) continue;  // its pieces' instances stand for it
    if (const auto* instance = std::get_if<Instance>(&geometry);
        instance != nullptr && !prototypes[instance->prototype])
      continue;  // its prototype's shapes stand for it (top_instances_inlined)
    EmbreeGeometry embree_geometry;
    std::visit(
        Overloaded{
            [&](const Instance& instance) {
              embree_geometry = new_instance_geometry(device, instance, prototypes[instance.prototype].get());
            },
            [&](const auto& shapes) { embree_geometry = new_embree_geometry(device, shapes, settings.quality); }},
        geometry);
    session.check("creation of geometry " + std::to_string(g) + " of " + where);
    rtcAttachGeometryByID(scene.get(), embree_geometry.get(), g);
    session.check("attaching geometry " + std::to_string(g) + " of " + where);
  }
  if (top != nullptr) {
    for (std::size_t k = 0; k < top->pieces.size(); ++k) {
      const auto id = static_cast<std::uint32_t>(top->hit_ids.pieces.first_instance + k);
      const EmbreeGeometry instance = new_piece_instance(device, top->pieces[k].get());
      session.check("creation of the instance of piece " + std::to_string(k));
      rtcAttachGeometryByID(scene.get(), instance.get(), id);
      session.check("attaching the instance of piece " + std::to_string(k));
    }
    for (std::size_t k = 0; k < top->hit_ids.inlined.size(); ++k) {
      const EmbreeInlinedShape& shape = top->hit_ids.inlined[k];
      const Instance& instance = std::get<Instance>(group.geometries[shape.instance]);
      const Geometry& geometry = prototype_groups[instance.prototype].geometries[shape.geometry];
      const std::string what = "geometry " + std::to_string(shape.geometry) + " of " +
                               group_name(static_cast<int>(instance.prototype)) + " in the top scene";
      EmbreeGeometry embree_geometry;
      std::visit(Overloaded{[](const Instance&) {},  // prototypes hold no instances (validate_group)
                            [&](const auto& shapes) {
                              embree_geometry = new_embree_geometry(device, shapes, settings.quality);
                            }},
                 geometry);
      session.check("creation of " + what);
      rtcAttachGeometryByID(scene.get(), embree_geometry.get(),
                            top->hit_ids.first_inlined + static_cast<std::uint32_t>(k));
      session.check("attaching " + what);
    }
  }
  rtcCommitScene(scene.get());
  session.check("the BVH build of " + where);
  return scene;
}

}  // namespace

EmbreeBuildSettings embree_build_settings(const BackendOptions& options) {
  EmbreeBuildSettings settings;
  // The context filter: coherent occlusion streams refuse candidates on triangles' edges with it
  // (embree_ray_batches.cpp); no other query sets one.
  settings.flags = static_cast<RTCSceneFlags>((options.embree_robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE) |
                                              RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  // Compact BVHs index the shared vertex arrays instead of copying triangles into their leaves:
  // on the dragon 31.6 instead of 58.0 MiB, for 20% fewer primary rays per second.
  if (options.embree_compact) settings.flags = static_cast<RTCSceneFlags>(settings.flags | RTC_SCENE_FLAG_COMPACT);
  switch (options.embree_quality) {
    case EmbreeBuildQuality::kLow: settings.quality = RTC_BUILD_QUALITY_LOW; break;
    case EmbreeBuildQuality::kMedium: settings.quality = RTC_BUILD_QUALITY_MEDIUM; break;
    case EmbreeBuildQuality::kHigh: settings.quality = RTC_BUILD_QUALITY_HIGH; break;
  }
  return settings;
}

EmbreeScenes build_embree_scenes(EmbreeDevice::Session& session, const RenderScene& scene,
                                 const EmbreeBuildSettings& settings) {
  for (std::size_t p = 0; p < scene.prototypes.size(); ++p)
    validate_group(scene.prototypes[p], static_cast<int>(p), {});
  validate_group(scene.top, -1, scene.prototype_bounds());

  std::vector<bool> inlined(scene.prototypes.size(), false);
  if (top_instances_inlined(scene, settings))
    for (const Geometry& geometry : scene.top.geometries)
      if (const auto* instance = std::get_if<Instance>(&geometry)) inlined[instance->prototype] = true;

  EmbreeScenes scenes;
  scenes.prototypes.reserve(scene.prototypes.size());
  for (std::size_t p = 0; p < scene.prototypes.size(); ++p)
    scenes.prototypes.push_back(
        inlined[p] ? EmbreeScene() : build_group(session, scene.prototypes[p], static_cast<int>(p), {}, {}, settings));
  scenes.hit_ids.pieces.first_instance = static_cast<std::uint32_t>(scene.top.geometries.size());
  for (std::uint32_t g = 0; g < scene.top.geometries.size(); ++g)
    if (built_in_pieces(scene.top.geometries[g]))
      build_pieces(session, std::get<TriangleMesh>(scene.top.geometries[g]), g, settings, scenes);
  scenes.hit_ids.first_inlined =
      scenes.hit_ids.pieces.first_instance + static_cast<std::uint32_t>(scenes.hit_ids.pieces.pieces.size());
  for (std::uint32_t g = 0; g < scene.top.geometries.size(); ++g) {
    const auto* instance = std::get_if<Instance>(&scene.top.geometries[g]);
    if (instance == nullptr || !inlined[instance->prototype]) continue;
    const Group& prototype = scene.prototypes[instance->prototype];
    for (std::uint32_t k = 0; k < prototype.geometries.size(); ++k)
      if (!is_empty(prototype.geometries[k])) scenes.hit_ids.inlined.push_back({g, k});
  }
  scenes.top = build_group(session, scene.top, -1, scene.prototypes, scenes.prototypes, settings, &scenes);
  return scenes;
}

}  // namespace rtpro
