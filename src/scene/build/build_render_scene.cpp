#include "rtpro/scene/build_render_scene.h"

#include "rtpro/core/error.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/core/overloaded.h"
#include "rtpro/scene/mesh_pieces.h"
#include "rtpro/scene/render_cost.h"
#include "traceable_range_check.h"
#include "gltf_asset.h"
#include "gltf_loader.h"
#include "gltf_motion.h"
#include "scene_materials.h"
#include "subdivided_mesh.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <type_traits>
#include <variant>

namespace rtpro {

namespace {

// A model the scene reader loaded (an entry's `loaded`, moved out of it): moved into the render
// scene when this is its only holder, copied when another entry or description still holds it.
template <typename Model>
Model taken_or_copied(std::shared_ptr<Model> model) {
  if (model.use_count() == 1) return std::move(*model);
  return *model;
}

class RenderSceneBuilder {
 public:
  RenderSceneBuilder(const SceneDescription& description, SceneBuildReport* report, const SceneBuildOptions& options)
      : description_(description),
        report_(report), subdivision_{description.camera, options,
                                      options.geometry_budget ? options.geometry_budget : default_memory_budget()},
        volume_budget_(options.volume_budget ? options.volume_budget : default_memory_budget()) {}

  RenderScene build() {
    scene_.camera = make_render_camera(description_.camera);
    scene_.render = description_.render;
    for (const LightDesc& light : description_.lights) scene_.lights.push_back(make_light(light));
    if (const std::optional<EnvironmentDesc>& e = description_.environment)
      scene_.environment = Environment{e->file, e->color * e->intensity, e->rotation, e->visible};
    if (description_.medium) scene_.world_medium = materials_.add_medium(*description_.medium);
    for (const MaterialDesc& m : description_.materials) materials_.add(m, m.name);
    std::uint64_t volume_budget = volume_budget_;
    for (const VolumeDesc& volume : description_.volumes) {
      GridMedium medium = make_grid_medium(volume, volume_budget);
      volume_budget -= std::min(volume_budget, medium.grid->memory.bytes);
      scene_.volumes.push_back(materials_.add_medium(medium));
    }

    check_instance_count();
    prototype_of_object_.assign(description_.objects.size(), std::nullopt);
    add_own_shapes(description_.world, scene_.top, true);
    for (const GltfDesc& gltf : description_.world.gltfs) {
      place_gltf(gltf, Affine::identity(), {});
      linking_of_object_.resize(scene_.top.geometries.size(), gltf.linking);
    }
    for (const InstanceDesc& instance : description_.world.instances) {
      flatten_instance(instance.object, instance.transform, instance.transform_steps, instance.where);
      linking_of_object_.resize(scene_.top.geometries.size(), instance.linking);
    }
    add_volume_boundaries();
    link_objects();
    check_traceable_range(scene_, top_origins_, description_.camera, description_.lights);
    if (report_) report_->flattened_instances = flattened_;
    return std::move(scene_);
  }

 private:
  // Each volume entry as Blender's Volume object: its grid's box, an interface into its medium
  // (scene/grid_medium.h's bounding_box_mesh), a top-level geometry of its own.
  void add_volume_boundaries() {
    for (std::size_t v = 0; v < scene_.volumes.size(); ++v) {
      TriangleMesh box = bounding_box_mesh(std::get<GridMedium>(scene_.media[scene_.volumes[v]]), 0);
      if (box.triangles.empty()) continue;
      box.material = materials_.add_volume_boundary(v);
      scene_.top.geometries.emplace_back(std::move(box));
      top_origins_.push_back({&description_.volumes[v].where});
      linking_of_object_.push_back(kNoLinking);
    }
  }

  // Counted before anything is flattened: a few nested levels of a few instances each multiply
  // to billions, which would otherwise cost minutes and gigabytes before failing. The error names
  // the world instance whose subtree crosses the limit.
  // glTF files are loaded here (once each, as placing them would), so their placements count
  // exactly; those of objects the world never places are loaded too.
  void check_instance_count() {
    const auto placements = [this](const GltfDesc& gltf) -> std::uint64_t {
      return gltf_prototypes(gltf).asset->placements.size();
    };
    const std::vector<std::uint64_t> per_object = flattened_instances_per_object(description_, placements);
    std::uint64_t count = 0;
    for (const GltfDesc& gltf : description_.world.gltfs) count = saturating_add(count, placements(gltf));
    for (const InstanceDesc& instance : description_.world.instances) {
      count = saturating_add(count, per_object[instance.object]);
      if (count > kMaxFlattenedInstances)
        throw InputError(
            instance.where,
            "instancing expands to " + (count == UINT64_MAX ? std::string("more than 2^64") : std::to_string(count)) +
                " instances after flattening nested instances; the limit is " + std::to_string(kMaxFlattenedInstances));
    }
  }

  // Spheres and meshes that belong to `object` itself (not through its instances). Only the
  // world's own shapes are top-level geometries, which need an origin and their entries' light
  // linking. Every list of shapes written in the scene file becomes one geometry of its kind
  // (shapes_from, in the kind's file: scene/sphere_geometry.h), linked entry by entry; glTF files
  // are placed as instances of their meshes (place_gltf).
  void add_own_shapes(const ObjectDesc& object, Group& group, bool world = false) {
    visit_shape_lists(object, Overloaded{[&](const std::vector<MeshDesc>& meshes) {
                                           for (const MeshDesc& mesh : meshes) {
                                             group.geometries.emplace_back(load_mesh(mesh));
                                             if (!world) continue;
                                             top_origins_.push_back({&mesh.where});
                                             linking_of_object_.push_back(mesh.linking);
                                           }
                                         },
                                         [](const std::vector<GltfDesc>&) {},
                                         [&](const std::vector<CurvesDesc>& curves) {
                                           for (const CurvesDesc& entry : curves) {
                                             group.geometries.emplace_back(load_curve_entry(entry));
                                             if (!world) continue;
                                             top_origins_.push_back({&entry.where});
                                             linking_of_object_.push_back(entry.linking);
                                           }
                                         },
                                         [&](const auto& shapes) { add_shape_list(shapes, group, world); }});
  }

  // One geometry of the object's list of a kind of shape; in the world, each entry linked as it says.
  template <typename Desc>
  void add_shape_list(const std::vector<Desc>& shapes, Group& group, bool world) {
    static_assert(std::is_constructible_v<Geometry, decltype(shapes_from(shapes))>,
                  "a kind of shape needs its alternative of Geometry and its GeometryKind (scene/render_scene.h)");
    if (shapes.empty()) return;
    group.geometries.emplace_back(shapes_from(shapes));
    if (!world) return;
    top_origins_.push_back({&scene_file_});
    linking_of_object_.push_back(kLinkedPerPrimitive);
    std::vector<std::uint32_t>& linkings = primitive_linkings_.emplace_back();
    for (const Desc& shape : shapes) linkings.push_back(shape.linking);
  }

  // Emitting curves are refused: the light set samples spheres and triangles only, and a fibre hit
  // only by BSDF samples would light the scene with noise alone.
  CurveSet load_curve_entry(const CurvesDesc& desc) {
    if (scene_.materials[desc.material].emission.emits())
      throw InputError(desc.where, "curves cannot emit light: material '" + scene_.material_names[desc.material] +
                                       "' has an emission; give the curves a material without one");
    return load_curves(desc);
  }

  TriangleMesh load_mesh(const MeshDesc& desc) {
    const auto start = std::chrono::steady_clock::now();
    LoadedMesh loaded = [&] {
      if (desc.loaded) return taken_or_copied(std::move(desc.loaded));
      try {
        return load_mesh_file(desc.file, MeshLoadOptions{desc.normals, desc.subdivision.has_value()});
      } catch (const InputError& e) {
        if (!e.where().file.empty()) throw;
        throw InputError(desc.where, e.message());
      }
    }();
    if (desc.subdivision) {
      const PolygonCage cage = loaded.cage ? *loaded.cage : cage_of_triangles(loaded.mesh);
      loaded.cage.reset();
      TriangleMesh refined =
          subdivide(cage, desc.subdivision, desc.displacement, desc.file, desc.where, loaded.stats.warnings);
      refined.name = loaded.mesh.name;
      refined.material = loaded.mesh.material;
      loaded.mesh = std::move(refined);
      loaded.stats.vertices = loaded.mesh.vertices.size();
      loaded.stats.triangles = loaded.mesh.triangles.size();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    TriangleMesh mesh = std::move(loaded.mesh);
    if (desc.material != kNoMaterial) {
      mesh.triangle_materials.clear();
      mesh.triangle_materials.shrink_to_fit();
      mesh.material = desc.material;
    } else if (loaded.materials.empty()) {
      mesh.triangle_materials.clear();
      mesh.material = 0;  // the scene's "default" material
    } else {
      // The file's MTL materials join the scene's list; remap the mesh's local indices.
      std::vector<std::uint32_t> remap;
      for (const MaterialDesc& m : loaded.materials)
        remap.push_back(materials_.add(m, desc.file.filename().string() + ":" + m.name));
      mesh.material = remap[std::min<std::size_t>(mesh.material, remap.size() - 1)];
      for (std::uint32_t& m : mesh.triangle_materials) m = remap[m];
    }
    if (report_) report_->meshes.push_back({desc.file.string(), loaded.stats, seconds});
    return mesh;
  }

  TriangleMesh subdivide(const PolygonCage& cage, const std::optional<SubdivisionDesc>& subdivision,
                         const std::optional<DisplacementDesc>& displacement, const std::filesystem::path& file,
                         const SourceLocation& where, std::vector<std::string>& warnings) {
    return subdivide_cage(cage, *subdivision, displacement ? &*displacement : nullptr, file.string(), where,
                          subdivision_, warnings);
  }

  // The prototype holding an object's own shapes, created on first use; none if it has none.
  std::optional<std::uint32_t> prototype_of(std::uint32_t object) {
    if (!prototype_of_object_[object]) {
      Group group;
      add_own_shapes(description_.objects[object], group);
      if (group.geometries.empty()) {
        prototype_of_object_[object] = kInvalidPrototype;
      } else {
        scene_.prototypes.push_back(std::move(group));
        prototype_of_object_[object] = static_cast<std::uint32_t>(scene_.prototypes.size() - 1);
      }
    }
    const std::uint32_t id = *prototype_of_object_[object];
    if (id == kInvalidPrototype) return std::nullopt;
    return id;
  }

  void add_instance(std::uint32_t prototype, const Affine& to_world, std::span<const Affine> to_world_steps,
                    const GeometryOrigin& origin) {
    if (++flattened_ > kMaxFlattenedInstances)
      throw geometry_error(origin, "instancing expands to more than " + std::to_string(kMaxFlattenedInstances) +
                                       " instances after flattening nested instances");
    const auto inverse_transform = inverse(to_world);
    if (!inverse_transform)
      throw geometry_error(origin, "instance transform (combined with its parents) is singular or not finite");
    for (const Affine& step : to_world_steps)
      if (!step.is_finite() || !inverse(step))
        throw geometry_error(origin,
                             "instance transform (combined with its parents) is singular or not finite "
                             "during the shutter");
    scene_.top.geometries.emplace_back(
        Instance{prototype, to_world, *inverse_transform, {to_world_steps.begin(), to_world_steps.end()}});
    top_origins_.push_back(origin);
  }

  // A glTF file loaded once per (file, normals, material) however often it is placed: each of its
  // meshes one prototype, each node drawing a mesh one instance.
  // The file posed at the frame (gltf_motion.h), its skinned and morphed meshes prototypes of their own.
  struct PlacedGltf {
    std::shared_ptr<const GltfAsset> asset;
    GltfPose pose;
    std::vector<std::optional<std::uint32_t>> prototype_of_mesh;      // none without triangles or drawn only deformed
    std::vector<std::optional<std::uint32_t>> prototype_of_deformed;  // per pose.deformed
  };

  const PlacedGltf& gltf_prototypes(const GltfDesc& desc) {
    // A subdivided entry's meshes are its own.
    const auto key = std::make_tuple(desc.file, int(desc.normals), desc.material,
                                     desc.subdivision ? desc.where.str() : std::string());
    if (const auto found = gltfs_.find(key); found != gltfs_.end()) return found->second;
    const auto start = std::chrono::steady_clock::now();
    std::shared_ptr<GltfAsset> asset = std::move(desc.loaded);
    if (!asset) {
      try {
        asset = std::make_shared<GltfAsset>(load_gltf_file(desc.file, MeshLoadOptions{desc.normals}));
      } catch (const InputError& e) {
        if (!e.where().file.empty()) throw;
        throw InputError(desc.where, e.message());
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (report_) report_->meshes.push_back({desc.file.string(), asset->stats, seconds});

    std::vector<std::uint32_t> remap;
    if (desc.material == kNoMaterial)
      for (const MaterialDesc& m : asset->materials)
        remap.push_back(materials_.add(m, desc.file.filename().string() + ":" + m.name));
    // Primitives without a material take the scene's "default", like shapes without one.
    const auto material = [&](std::uint32_t m) {
      return desc.material != kNoMaterial ? desc.material : m == kNoMaterial ? 0u : remap[m];
    };
    // Only the placements are read from here on: the meshes move into the prototypes unless
    // another entry or description still holds the asset.
    const bool sole_holder = asset.use_count() == 1;
    PlacedGltf placed{asset,
                      pose_gltf_frame(*asset, description_.frame, description_.render.fps, description_.camera.shutter),
                      {},
                      {}};
    const auto add_prototype = [&](TriangleMesh& source, bool movable) -> std::optional<std::uint32_t> {
      if (source.triangles.empty()) return std::nullopt;
      TriangleMesh mesh =
          desc.subdivision ? subdivided_gltf_mesh(desc, source) : (movable ? std::move(source) : source);
      mesh.material = material(mesh.material);
      if (desc.material != kNoMaterial) mesh.triangle_materials = {};
      for (std::uint32_t& m : mesh.triangle_materials) m = material(m);
      Group group;
      group.geometries.emplace_back(std::move(mesh));
      scene_.prototypes.push_back(std::move(group));
      return static_cast<std::uint32_t>(scene_.prototypes.size() - 1);
    };
    // A mesh that every node draws deformed needs no prototype (nor a BVH) of its own.
    std::vector<bool> drawn_as_is(asset->meshes.size(), false);
    for (const GltfPlacement& p : placed.pose.placements)
      if (p.deformed < 0) drawn_as_is[p.mesh] = true;
    for (std::size_t m = 0; m < asset->meshes.size(); ++m)
      placed.prototype_of_mesh.push_back(drawn_as_is[m] ? add_prototype(asset->meshes[m], sole_holder) : std::nullopt);
    // The posed meshes are the placement's own.
    for (TriangleMesh& source : placed.pose.deformed)
      placed.prototype_of_deformed.push_back(add_prototype(source, true));
    return gltfs_.emplace(key, std::move(placed)).first->second;
  }

  // glTF has no subdivision of its own: an entry asking for one refines each of the file's meshes,
  // its triangles welded into a cage.
  TriangleMesh subdivided_gltf_mesh(const GltfDesc& desc, const TriangleMesh& source) {
    std::vector<std::string> warnings;
    TriangleMesh mesh =
        subdivide(cage_of_triangles(source), desc.subdivision, desc.displacement, desc.file, desc.where, warnings);
    mesh.name = source.name;
    mesh.material = source.material;
    if (report_)
      for (std::string& warning : warnings) report_->meshes.back().stats.warnings.push_back(std::move(warning));
    return mesh;
  }

  // `to_world_steps`: the placement's time steps (scene/motion.h), empty when it does not move.
  void place_gltf(const GltfDesc& desc, const Affine& to_world, std::span<const Affine> to_world_steps) {
    const PlacedGltf& placed = gltf_prototypes(desc);
    for (const GltfPlacement& p : placed.pose.placements) {
      const auto prototype =
          p.deformed >= 0 ? placed.prototype_of_deformed[std::size_t(p.deformed)] : placed.prototype_of_mesh[p.mesh];
      if (!prototype) continue;
      add_instance(*prototype, compose(to_world, p.transform),
                   compose_steps(to_world, to_world_steps, p.transform, p.transform_steps),
                   {&desc.where, &desc.file, p.node});
    }
  }

  void flatten_instance(std::uint32_t object, const Affine& to_world, std::span<const Affine> to_world_steps,
                        const SourceLocation& where) {
    if (const auto prototype = prototype_of(object)) add_instance(*prototype, to_world, to_world_steps, {&where});
    for (const GltfDesc& gltf : description_.objects[object].gltfs) place_gltf(gltf, to_world, to_world_steps);
    for (const InstanceDesc& nested : description_.objects[object].instances)
      flatten_instance(nested.object, compose(to_world, nested.transform),
                       compose_steps(to_world, to_world_steps, nested.transform, nested.transform_steps), nested.where);
  }

  // Light linking: the group of each top-level object (none when no world entry is linked), per
  // primitive for a geometry of many entries.
  void link_objects() {
    if (description_.linkings.empty()) return;
    LightLinks& links = scene_.links;
    std::vector<std::uint32_t> group_of_linking;
    for (const LightLinkingDesc& linking : description_.linkings)
      group_of_linking.push_back(links.group_with(make_link_group(linking, description_.lights.size())));
    const auto group = [&](std::uint32_t linking) { return linking == kNoLinking ? 0u : group_of_linking[linking]; };
    std::size_t next_per_primitive = 0;
    for (const std::uint32_t linking : linking_of_object_) {
      if (linking != kLinkedPerPrimitive) {
        links.group_of_object.push_back(group(linking));
        continue;
      }
      links.group_of_object.push_back(LightLinks::kPerPrimitive |
                                      static_cast<std::uint32_t>(links.group_of_primitive.size()));
      for (const std::uint32_t entry : primitive_linkings_[next_per_primitive++])
        links.group_of_primitive.push_back(group(entry));
    }
  }

  static constexpr std::uint32_t kInvalidPrototype = ~0u;
  const SceneDescription& description_;
  SceneBuildReport* report_;
  SubdivisionContext subdivision_;
  std::uint64_t volume_budget_;  // bytes the volumes' grids may take between them
  RenderScene scene_;
  SceneMaterials materials_{scene_};
  std::vector<std::optional<std::uint32_t>> prototype_of_object_;
  std::map<std::tuple<std::filesystem::path, int, std::uint32_t, std::string>, PlacedGltf> gltfs_;
  std::size_t flattened_ = 0;
  const SourceLocation scene_file_{description_.file.string()};  // where the world's spheres are
  std::vector<GeometryOrigin> top_origins_;                      // where each top-level geometry came from
  // Per top-level geometry: its world entry's linking, or kLinkedPerPrimitive for a geometry of
  // many entries, whose entries' linkings are the next list of primitive_linkings_.
  std::vector<std::uint32_t> linking_of_object_;
  std::vector<std::vector<std::uint32_t>> primitive_linkings_;
  static constexpr std::uint32_t kLinkedPerPrimitive = kNoLinking - 1;  // not an index: linkings < kMaxSceneEntries
};

// One mesh at a time, so that no more than one mesh's normals are held twice.
void pack_mesh_normals(RenderScene& scene) {
  const auto pack = [](Group& group) {
    for (Geometry& geometry : group.geometries)
      if (auto* mesh = std::get_if<TriangleMesh>(&geometry)) mesh->pack_normals();
  };
  pack(scene.top);
  for (Group& prototype : scene.prototypes) pack(prototype);
}

// The top group's only: Embree instances one level deep, so a prototype's mesh cannot become
// instanced pieces.
void order_meshes_in_pieces(RenderScene& scene, std::uint32_t piece_triangles) {
  for (Geometry& geometry : scene.top.geometries)
    if (auto* mesh = std::get_if<TriangleMesh>(&geometry)) order_in_pieces(*mesh, piece_triangles);
}

// What the build does to the whole scene once every entry is in.
void finish_render_scene(RenderScene& scene, const SceneBuildOptions& options) {
  if (options.compact_normals) pack_mesh_normals(scene);
  if (options.piece_triangles != 0) order_meshes_in_pieces(scene, options.piece_triangles);
}

}  // namespace

RenderScene build_render_scene(const SceneDescription& description, SceneBuildReport* report,
                               const SceneBuildOptions& options) {
  // A shallow copy: the loaded models it shares with `description` are copied, never taken.
  const SceneDescription shared = description;
  RenderScene scene = RenderSceneBuilder(shared, report, options).build();
  finish_render_scene(scene, options);
  return scene;
}

RenderScene build_render_scene_taking_models(SceneDescription& description, SceneBuildReport* report,
                                             const SceneBuildOptions& options) {
  RenderScene scene = RenderSceneBuilder(description, report, options).build();
  finish_render_scene(scene, options);
  // An entry placing a glTF file another entry placed alike was never read: it lets go too.
  for (GltfDesc& gltf : description.world.gltfs) gltf.loaded.reset();
  return scene;
}

}  // namespace rtpro
