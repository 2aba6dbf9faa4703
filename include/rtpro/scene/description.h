#pragma once
// The scene description: what a scene file says, validated and with names resolved, but nothing
// loaded yet (meshes are still paths). Produced by the scene parser, consumed by
// build_render_scene().
#include "rtpro/core/error.h"
#include "rtpro/core/texture_sampling.h"
#include "rtpro/core/transform.h"
#include "rtpro/core/vec3.h"
#include "rtpro/scene/checker_axes.h"
#include "rtpro/scene/light.h"  // LightDesc
#include "rtpro/scene/material_kinds.h"
#include "rtpro/scene/material_textures.h"
#include "rtpro/scene/medium_kinds.h"
#include "rtpro/scene/motion.h"
#include "rtpro/scene/render_settings.h"
// Each kind of shape's scene side (its entries' type and reader, its shapes and their bounds),
// here so that whatever visits the lists below finds the kind's functions.
#include "rtpro/scene/curve_geometry.h"
#include "rtpro/scene/sphere_geometry.h"
#include "rtpro/scene/subdivision.h"
#include "rtpro/scene/triangle_geometry.h"
#include "rtpro/scene/volume_desc.h"

#include <concepts>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rtpro {

inline constexpr int kSceneFormatVersion = 1;

// How the camera maps directions to the film: through a point (perspective: `fov`) or along
// parallel rays from the plane through its position (orthographic: `ortho_height`).
enum class CameraProjection { kPerspective, kOrthographic };

struct CameraDesc {
  Vec3 position{0.0f, 0.0f, -5.0f};
  Vec3 look_at{0.0f, 0.0f, 0.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  CameraProjection projection = CameraProjection::kPerspective;
  float fov_degrees = 45.0f;  // vertical field of view (perspective)
  float ortho_height = 2.0f;  // the view's height in scene units (orthographic)
  int width = 640;
  int height = 480;
  // Thin lens: the lens radius in scene units (0: a pinhole, everything sharp) and the distance
  // along the view direction that is in focus (0: the distance to look_at).
  float aperture = 0.0f;
  float focus_distance = 0.0f;
  // `camera.shutter`: the exposure in frames relative to the frame's time (scene/motion.h).
  Shutter shutter;
  // A camera that moves during the shutter: its frame (camera_frame, build_render_scene.h) at the
  // shutter's time steps; empty when it stands still.
  std::vector<Affine> frame_steps;
};

// A procedural checkerboard in world space: squares (or cubes) of side `size`, alternating
// between two colours, the square containing the origin's positive corner `even`.
struct CheckerDesc {
  float size = 1.0f;
  Color even{0.8f}, odd{0.1f};
  CheckerAxes axes = CheckerAxes::kXZ;
};

// A material as the scene file (or an MTL library, or a glTF file) describes it: what every kind
// has here, the kind's own parameters in `params` (scene/material_kinds.h).
struct MaterialDesc {
  std::string name;
  MaterialParams params;  // its alternative is the material's kind (`type:` in the scene file)
  // Emitted radiance (colour × strength), on the front side of a surface (the side its normal
  // points to; a sphere's outside) or on both. Lights the scene under the path integrator.
  Color emission{0.0f};
  bool emission_two_sided = false;
  std::optional<TextureSlotDesc> emission_texture;  // multiplies `emission` (glTF emissiveTexture)
  Color color{0.8f, 0.8f, 0.8f};                    // diffuse (and ambient) colour; principled's base colour
  std::optional<CheckerDesc> checker;               // when set, the diffuse colour instead of `color`
  // An image whose colour multiplies `color` (`color: {texture: ...}`, MTL map_Kd, glTF
  // baseColorTexture), looked up at the surface's texture coordinates; decoded from
  // `texture_colorspace` (an OpenColorIO colour space) to scene-linear first.
  std::filesystem::path color_texture;
  std::string texture_colorspace = "sRGB - Texture";
  TextureSampling texture_sampling{};  // `wrap:` and `filter:`; a glTF texture's sampler
  SourceLocation texture_where;        // where the texture was named, for a missing file
  // An image stored inside a glTF: its encoded bytes (color_texture then names it, e.g.
  // "model.glb#images[0].png", the extension telling its format).
  std::shared_ptr<const std::vector<unsigned char>> texture_bytes;
  float opacity = 1.0f;  // MTL d (or 1 - Tr), glTF baseColorFactor alpha; not rendered yet
  // The medium inside the surface (`interior:`, glTF KHR_materials_volume); unset, a kind whose
  // inside is glass has its absorption (or vacuum), the others bound no medium.
  std::optional<Medium> interior;
};

// How a mesh entry gets its shading normals (`normals:` in the scene file).
enum class NormalsMode : std::uint8_t {
  kAuto,    // what the file says: its normals, OBJ smoothing groups, otherwise flat
  kFlat,    // face normals everywhere, the file's normals and groups ignored
  kSmooth,  // area-weighted normals across every shared vertex, the file's ignored
  kFile,    // the file's normals; an input error when it has none
};

inline constexpr std::uint32_t kNoMaterial = ~0u;

// Lights named by a world entry's `light_linking:` or `shadow_linking:` (scenes/FORMAT.md, "Light
// linking"): indices into SceneDescription::lights, either the only ones that count (include:
// illuminated_by, shadows_from) or the ones left out (not_illuminated_by, no_shadows_from).
struct LightListDesc {
  bool include = false;
  std::vector<std::uint32_t> lights;
};

// Which lights illuminate a world entry and which lights' shadow rays it blocks; unset: all of them.
struct LightLinkingDesc {
  std::optional<LightListDesc> illumination;
  std::optional<LightListDesc> shadows;
};

// An entry without light linking (the index of a LightLinkingDesc otherwise).
inline constexpr std::uint32_t kNoLinking = ~0u;

struct SphereDesc {
  Vec3 center;  // at the frame's time
  // The centre at each time step of the shutter (scene/motion.h); empty: the sphere does not move.
  std::vector<Vec3> center_steps = {};
  float radius = 1.0f;
  std::uint32_t material = 0;          // index into SceneDescription::materials
  std::uint32_t linking = kNoLinking;  // index into SceneDescription::linkings (world entries only)
};

struct LoadedMesh;  // scene/mesh_loader.h

struct MeshDesc {
  std::filesystem::path file;            // resolved against the scene file's folder
  std::uint32_t material = kNoMaterial;  // overrides the OBJ's own materials when set
  SourceLocation where;                  // of the entry in the scene file, for load errors
  NormalsMode normals = NormalsMode::kAuto;
  std::uint32_t linking = kNoLinking;
  // Set when the file was already loaded while the scene was read (a mesh file as the whole scene
  // needs its bounds then); otherwise loaded by build_render_scene. Mutable, as a cache: the
  // render scene takes the mesh over when nothing else holds it (build_render_scene_taking_models).
  mutable std::shared_ptr<LoadedMesh> loaded = nullptr;
  std::optional<SubdivisionDesc> subdivision = std::nullopt;  // the file's faces refined as a cage
  std::optional<DisplacementDesc> displacement = std::nullopt;
};

struct GltfAsset;  // a loaded glTF file (src/scene/gltf/gltf_asset.h)

// A glTF 2.0 file (.gltf or .glb) placed as a whole: its node hierarchy becomes instances.
struct GltfDesc {
  std::filesystem::path file;
  std::uint32_t material = kNoMaterial;  // overrides the file's materials when set
  SourceLocation where;
  NormalsMode normals = NormalsMode::kAuto;
  // Set when the file was already loaded while the scene was read (a glTF file as the whole
  // scene needs its cameras, lights and bounds then); otherwise loaded by build_render_scene,
  // which takes its meshes over as MeshDesc::loaded says.
  mutable std::shared_ptr<GltfAsset> loaded;
  std::uint32_t linking = kNoLinking;                         // every instance the file places
  std::optional<SubdivisionDesc> subdivision = std::nullopt;  // every mesh of the file refined
  std::optional<DisplacementDesc> displacement = std::nullopt;
};

struct InstanceDesc {
  std::uint32_t object = 0;  // index into SceneDescription::objects
  Affine transform;          // object to parent, at the frame's time
  // Object to parent at each time step of the shutter (scene/motion.h); empty: static.
  std::vector<Affine> transform_steps = {};
  SourceLocation where;
  std::uint32_t linking = kNoLinking;  // every instance this one expands to
};

// A set of shapes: either a named object (instanced by name) or the world itself.
struct ObjectDesc {
  std::string name;
  std::vector<SphereDesc> spheres;
  std::vector<MeshDesc> meshes;
  std::vector<GltfDesc> gltfs;
  std::vector<CurvesDesc> curves;
  std::vector<InstanceDesc> instances;
};

// Calls visit(shapes) with the object's list of each kind of shape, in this order: a visitor
// without an overload for a new kind of shape does not compile. `Object` is ObjectDesc or a const
// one, for readers that fill the lists and users that read them.
template <typename Object, typename Visit>
requires std::same_as<std::remove_const_t<Object>, ObjectDesc>
void visit_shape_lists(Object& object, Visit&& visit) {
  visit(object.spheres);
  visit(object.meshes);
  visit(object.gltfs);
  visit(object.curves);
}

// `environment:` at the top of a scene file: what arrives where rays escape (see scenes/FORMAT.md).
struct EnvironmentDesc {
  std::filesystem::path file;  // empty: a constant environment of `color`
  SourceLocation file_where;
  Color color{1.0f};  // with a file: a tint multiplying the image
  float intensity = 1.0f;
  Affine rotation;  // image frame to world
  bool visible = true;
};

struct SceneDescription {
  std::filesystem::path file;
  // Every scene text file the parser read: the file itself (unless it came from standard input)
  // and each include. With the meshes and glTF files of the objects, these are what a pixel can
  // depend on besides the settings: a resume journal and the ranks of a job hash them.
  std::vector<std::filesystem::path> source_files;
  CameraDesc camera;
  RenderSettings render;
  // The frame rendered: the scene variable `frame` (--frames sets it), 1 when unset. A glTF file
  // is posed at frame / render.fps seconds.
  double frame = 1.0;
  std::vector<MaterialDesc> materials;  // index 0 is always "default"
  std::vector<LightDesc> lights;
  std::vector<std::string> light_names;  // one per light: its `name:`, empty when it has none
  // One per light: where a model file's light came from and the value the file gave before rtpro
  // converted it ("nodes[1] (extensions.KHR_lights_punctual.lights[0]): 1000 cd at 683 lm/W"),
  // what `rtpro info` shows beside the value rendered; empty for a scene file's own lights.
  std::vector<std::string> light_sources;
  std::optional<EnvironmentDesc> environment;
  std::optional<Medium> medium;            // `medium:`: what fills the world outside every object
  std::vector<ObjectDesc> objects;         // named, reachable only through instances
  ObjectDesc world;                        // what is rendered
  std::vector<VolumeDesc> volumes;         // the world's `volume` entries
  std::vector<LightLinkingDesc> linkings;  // of the world's entries that have one
  // What rtpro chose for a model file read as the whole scene (the camera framing it, the light it
  // added), one line each, for the commands to say.
  std::vector<std::string> notes;
};

}  // namespace rtpro
