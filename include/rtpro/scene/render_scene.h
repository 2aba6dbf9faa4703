#pragma once
// The immutable render scene: everything a backend and the shading need, fully loaded, with
// instances flattened to one level (top-level group → prototype groups).
#include "rtpro/core/bbox.h"
#include "rtpro/core/error.h"
#include "rtpro/core/texture_wrap.h"
#include "rtpro/core/transform.h"
#include "rtpro/scene/checker_axes.h"
#include "rtpro/scene/light.h"
#include "rtpro/scene/light_links.h"
#include "rtpro/scene/render_camera.h"
#include "rtpro/scene/render_settings.h"
#include "rtpro/scene/sphere_geometry.h"
#include "rtpro/scene/triangle_geometry.h"

#include <cstdint>
#include <memory>
#include <filesystem>
#include <string>
#include <optional>
#include <span>
#include <variant>
#include <vector>

namespace rtpro {

struct Instance {
  std::uint32_t prototype;  // index into RenderScene::prototypes
  Affine object_to_world;
  Affine world_to_object;
};

// One geometry of a group; its index in the group is the geometry id a hit reports. Each kind of
// shape has a home of its own on each side of the modules (scene/sphere_geometry.h, the backend's
// and the renderer's per-kind files); an Instance places a prototype group.
using Geometry = std::variant<SphereSet, TriangleMesh, Instance>;

enum class GeometryKind : std::uint8_t { kSpheres = 0, kTriangles = 1, kInstance = 2 };
inline GeometryKind kind_of(const Geometry& g) { return static_cast<GeometryKind>(g.index()); }
// A new geometry alternative needs its GeometryKind; switches over the kind are compiled with
// -Werror=switch, so each one that misses the new kind stops the build.
static_assert(std::variant_size_v<Geometry> == 3, "add the new alternative to GeometryKind");

struct Group {
  std::vector<Geometry> geometries;
  // Primitive count of geometry g (spheres, triangles, or 1 for an instance).
  std::uint32_t primitive_count(std::uint32_t g) const;
  // Instances need their prototype's bounds: callers compute RenderScene::prototype_bounds()
  // once rather than walking a large prototype again for every instance of it.
  BBox primitive_bounds(std::uint32_t g, std::uint32_t prim, std::span<const BBox> prototype_bounds) const;
  BBox bounds(std::span<const BBox> prototype_bounds) const;
};

// A checkerboard as shading evaluates it (CheckerDesc, with the reciprocal size).
// Two named colours, not an array: with `Color colors[2]` here GCC 12.2 (-O1 and above) copied
// the Color alternative of ColorTexture as (x, x, y) in build_render_scene.cpp — every material's
// colour wrong, found by the regression images; clang was right.
struct CheckerTexture {
  float inv_size;
  Color even, odd;  // the square containing the origin's positive corner is even
  CheckerAxes axes;
};

// A material's diffuse colour: constant, or a texture evaluated at the shading point
// (render/texture.h). Adding a kind fails to compile where it is not evaluated.
// An image texture (RenderScene::textures[image]) times `tint`, at the surface's texture
// coordinates.
struct ImageTexture {
  std::uint32_t image;
  Color tint;
  TextureWrap wrap;
};

using ColorTexture = std::variant<Color, CheckerTexture, ImageTexture>;

// An image file a texture reads, and the OpenColorIO colour space its values are encoded in.
struct TextureImage {
  std::filesystem::path file;
  std::string colorspace;
  // An image stored inside a glTF: its encoded bytes (`file` then only names it).
  std::shared_ptr<const std::vector<unsigned char>> bytes;
  SourceLocation where{};  // the key that named it first, for messages about the image
};

// A tangent-space normal map (glTF normalTexture): the image's RGB in [0, 1] read as a normal in
// the frame of the surface's tangent (increasing u), bitangent (increasing v) and normal; x and y
// scaled by `scale`.
struct NormalMap {
  std::uint32_t image;
  float scale;
};

// A smooth dielectric (glass, water): refraction index and interior absorption.
struct Dielectric {
  float ior;
  Color transmittance;  // of white light after `transmittance_distance`
  float transmittance_distance;
};

// What the path integrator evaluates at a surface (render/material_bsdf.h makes its BSDF).
// PhongSurface: the Whitted fields below, read as a Lambert surface of `color` (glass, with a
// dielectric, as smooth glass). The others take their colour from Material::color.
struct PhongSurface {};
struct DiffuseSurface {};  // Lambert, reflectance `color`
struct ConductorSurface {
  float roughness;
  // A complex index eta + i·k per channel; without one, `color` is the reflectance at normal
  // incidence.
  bool has_complex_ior;
  Color eta, k;
};
struct DielectricSurface {
  float roughness;  // index and absorption in Material::dielectric
};
// The glTF 2.0 metallic-roughness model (render/principled_bsdf.h). Its base colour is its own
// (Material::color holds the Whitted approximation's diffuse colour); index of refraction 1.5 unless
// Material::dielectric says otherwise.
struct PrincipledSurface {
  ColorTexture base_color;
  float metalness, roughness, ior;
  float specular_weight;
  Color specular_color;
  float transmission_weight;
  float coat_weight, coat_roughness;
  Color fuzz_color;
  float fuzz_roughness;
  // roughness × green and metalness × blue of an image (its tint is (1, roughness, metalness)).
  std::optional<ImageTexture> metallic_roughness;
  std::optional<NormalMap> normal_map;
};
using SurfaceModel = std::variant<PhongSurface, DiffuseSurface, ConductorSurface, DielectricSurface, PrincipledSurface>;

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

// A material as both integrators see it. The Whitted fields (colour, Phong highlight, mirror
// reflectivity, glass) are set for every kind, physically based kinds approximated there, so the
// whitted integrator renders any scene; the path integrator reads `model`.
struct Material {
  ColorTexture color;
  float specular;
  float shininess;
  float reflectivity;
  std::optional<Dielectric> dielectric;  // glass: no diffuse part, Fresnel reflection and refraction
  SurfaceModel model = PhongSurface{};
  Emission emission{};
};

// Light from infinitely far away in every direction a ray escapes along: a latitude-longitude
// image (read by the caller, see render/environment_light.h) or, without a file, a constant.
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
  std::vector<TextureImage> textures;  // each file and colour space once
  Group top;                           // may contain instances
  std::vector<Group> prototypes;       // never contain instances

  std::vector<BBox> prototype_bounds() const;
  BBox bounds() const { return top.bounds(prototype_bounds()); }
};

}  // namespace rtpro
