#pragma once
// The immutable render scene: everything a backend and the shading need, fully loaded, with
// instances flattened to one level (top-level group → prototype groups).
#include "rtpro/core/bbox.h"
#include "rtpro/core/error.h"
#include "rtpro/core/texture_sampling.h"
#include "rtpro/core/transform.h"
#include "rtpro/scene/checker_axes.h"
#include "rtpro/scene/curve_geometry.h"
#include "rtpro/scene/light.h"
#include "rtpro/scene/light_links.h"
#include "rtpro/scene/material_kinds.h"
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/medium_kinds.h"
#include "rtpro/scene/motion.h"
#include "rtpro/scene/render_camera.h"
#include "rtpro/scene/render_settings.h"
#include "rtpro/scene/sphere_geometry.h"
#include "rtpro/scene/triangle_geometry.h"
#include "rtpro/scene/whitted_material.h"

#include <cstdint>
#include <memory>
#include <filesystem>
#include <string>
#include <optional>
#include <span>
#include <variant>
#include <vector>
#include <cstring>

namespace rtpro {

struct Instance {
  std::uint32_t prototype;  // index into RenderScene::prototypes
  Affine object_to_world;   // at the frame's time
  Affine world_to_object;
  // object_to_world at each time step of the shutter (scene/motion.h); empty: static. The
  // transform at a ray's time is interpolated from these and inverted.
  std::vector<Affine> object_to_world_steps = {};

  bool moving() const { return !object_to_world_steps.empty(); }
  // Static and placed by the identity, bit for bit: a ray in its prototype's space has the ray's
  // own coordinates, so a backend may trace the prototype's shapes as if they stood in the top group.
  bool places_as_is() const {
    const Affine identity;
    return !moving() && std::memcmp(&object_to_world, &identity, sizeof(Affine)) == 0;
  }
};

// A moving instance's placement at ray time `time` in [0, 1] and its inverse (nothing when the
// interpolated matrix is singular: the instance is then missed at that time).
struct InstancePlacement {
  Affine object_to_world, world_to_object;
};
std::optional<InstancePlacement> placement_at(const Instance& instance, float time);

// One geometry of a group; its index in the group is the geometry id a hit reports. Each kind of
// shape has a home of its own on each side of the modules (scene/sphere_geometry.h, the backend's
// and the renderer's per-kind files); an Instance places a prototype group.
using Geometry = std::variant<SphereSet, TriangleMesh, Instance, CurveSet>;

enum class GeometryKind : std::uint8_t { kSpheres = 0, kTriangles = 1, kInstance = 2, kCurves = 3 };
inline GeometryKind kind_of(const Geometry& g) { return static_cast<GeometryKind>(g.index()); }
// A new geometry alternative needs its GeometryKind; switches over the kind are compiled with
// -Werror=switch, so each one that misses the new kind stops the build.
static_assert(std::variant_size_v<Geometry> == 4, "add the new alternative to GeometryKind");

struct Group {
  std::vector<Geometry> geometries;
  // Primitive count of geometry g (spheres, triangles, curve segments, or 1 for an instance).
  std::uint32_t primitive_count(std::uint32_t g) const;
  // Instances need their prototype's bounds: callers compute RenderScene::prototype_bounds()
  // once rather than walking a large prototype again for every instance of it.
  BBox primitive_bounds(std::uint32_t g, std::uint32_t prim, std::span<const BBox> prototype_bounds) const;
  // Time steps of geometry g's motion (scene/motion.h), 0 where it keeps still, and primitive
  // prim's bounds at one of them: between two steps it lies within the two boxes' interpolation.
  std::uint32_t motion_step_count(std::uint32_t g) const;
  BBox primitive_bounds_at_step(std::uint32_t g, std::uint32_t prim, std::uint32_t step,
                                std::span<const BBox> prototype_bounds) const;
  BBox bounds(std::span<const BBox> prototype_bounds) const;
};

// Radiance a surface emits: from its front side (where its normal points; a sphere's outside) or
// from both.
struct Emission {
  Color radiance{0.0f};
  bool two_sided = false;
  // radiance × the image's colour at the point's texture coordinates (its tint is white); lights
  // are still picked by `radiance`, the most the surface emits.
  std::optional<ImageTexture> texture;
  bool emits() const { return radiance.x > 0.0f || radiance.y > 0.0f || radiance.z > 0.0f; }
};

// A material as both integrators see it. What every kind has is Material's own: the base colour
// (the Lambert reflectance, a conductor's reflectance at normal incidence, principled's base
// colour: what the kind's bsdf_from reads) and the emission. The kind itself is `model`, which
// the path integrator shades; `whitted` is the kind's Whitted approximation
// (whitted_approximation_of, in the kind's header), which the whitted integrator alone reads.
struct Material {
  ColorTexture base_color;
  Emission emission{};
  SurfaceModel model = PhongSurface{};
  WhittedMaterial whitted;
  // The medium inside the surface (an index into RenderScene::media, kNoMedium for vacuum) when the
  // surface bounds one: a path refracted (or passing) through it from the front is in that medium
  // until it crosses such a surface from the back. Unset: what crosses it stays where it was.
  std::optional<MediumIndex> interior = std::nullopt;
  // `type: interface`: no surface, only a medium's boundary: rays pass straight through.
  bool index_matched = false;
};

// The medium inside the material's surface, whose absorption a path through it takes: its kind's
// (interior_of, in the kind's header); nullptr when it has none.
inline const Dielectric* interior_of(const Material& material) {
  return std::visit([](const auto& surface) { return interior_of(surface); }, material.model);
}

// Light from infinitely far away in every direction a ray escapes along: a latitude-longitude
// image (read by the caller, see render/environment_light.h) or, without a file, a constant.
// The most radiance an environment may send along any direction (a pixel's value × colour ×
// intensity, per channel): far above any sky or sun, and far enough below the 32-bit float's
// 3.4e38 that sums of samples and their squares stay finite (3e38 made every pixel infinite).
inline constexpr float kMaxEnvironmentRadiance = 1e12f;

struct Environment {
  std::filesystem::path file;  // empty: a constant environment of radiance `scale`
  Color scale{1.0f};           // colour × intensity, multiplying the image's values
  Affine to_world;             // rotation from the image's frame to the world
  bool visible = true;         // false: camera rays that escape see render.background instead
};

struct RenderScene {
  RenderCamera camera;
  RenderSettings render;
  std::vector<Material> materials;
  std::vector<std::string> material_names;
  std::vector<Light> lights;
  LightLinks links;  // which lights reach which top-level objects, and whose shadows they cast
  std::optional<Environment> environment;
  std::vector<Medium> media;             // the materials' interiors, the world's and the volumes'
  MediumIndex world_medium = kNoMedium;  // what fills the world outside every object
  std::vector<TextureImage> textures;    // each file and colour space once
  Group top;                             // may contain instances
  std::vector<Group> prototypes;         // never contain instances
  std::vector<MediumIndex> volumes;      // the world's volume entries: their media (GridMedium)

  std::vector<BBox> prototype_bounds() const;
  BBox bounds() const { return top.bounds(prototype_bounds()); }
};

}  // namespace rtpro
