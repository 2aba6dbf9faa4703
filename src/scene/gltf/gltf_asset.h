#pragma once
// A glTF 2.0 file as rtpro uses it: one triangle mesh per glTF mesh (its primitives merged), the
// materials mapped onto rtpro's model, and the node hierarchy resolved to world placements of
// meshes, cameras and lights. See gltf_loader.h for what is read and how it is validated.
#include "gltf_animation.h"
#include "gltf_deformation.h"
#include "gltf_quaternion.h"
#include "gltf_skin.h"
#include "rtpro/core/bbox.h"
#include "rtpro/core/transform.h"
#include "rtpro/scene/description.h"
#include "rtpro/scene/mesh.h"
#include "rtpro/scene/mesh_loader.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {

// The JSON path of nodes[node], which errors about what the node places name.
std::string gltf_node_path(std::uint32_t node);

// A node that draws a mesh: meshes[mesh] placed by `transform` (object to the glTF's world).
struct GltfPlacement {
  std::uint32_t mesh;
  std::uint32_t node;  // the index of the node in nodes[]
  Affine transform;
  // The mesh as the node's skin or morph weights pose it: an index into GltfPose::deformed, which
  // `transform` places (the identity for a skinned mesh, whose joints place it); -1: meshes[mesh].
  std::int32_t deformed = -1;
  // `transform` at each time step of the shutter (scene/motion.h); empty: still during it.
  std::vector<Affine> transform_steps = {};
};

struct GltfCamera {
  std::uint32_t node;  // nodes[node] places cameras[camera]
  std::uint32_t camera;
  Vec3 position;
  Vec3 forward;        // the node's -z
  Vec3 up;             // the node's +y
  float yfov_degrees;  // perspective
  float aspect_ratio;  // width / height; 0 when the file gives none
  // An orthographic camera's half height (glTF's ymag; its xmag gives the aspect ratio); 0 for a
  // perspective one.
  float ortho_half_height = 0.0f;
};

struct GltfLight {
  enum class Kind : std::uint8_t { kPoint, kDirectional, kSpot };
  Kind kind;
  std::uint32_t node;  // nodes[node] places extensions.KHR_lights_punctual.lights[light]
  std::uint32_t light;
  Vec3 position;   // point and spot
  Vec3 direction;  // directional and spot: the direction light travels in (the node's -z)
  Color color;
  float intensity;  // as the file says: candela (point, spot) or lux (directional)
  // Spot: the cone's half-angles in radians, 0 <= inner <= outer <= π/2 (a light's spot.innerConeAngle
  // and spot.outerConeAngle, default 0 and π/4).
  float inner_cone_angle;
  float outer_cone_angle;
};

// A node as the file places it, before animation: `matrix`, or translation, rotation and scale.
struct GltfNode {
  static constexpr std::uint32_t kNoParent = ~0u;
  std::uint32_t parent = kNoParent;
  std::optional<Affine> matrix;  // not animated (the specification forbids animating such nodes)
  Vec3 translation{0.0f}, scale{1.0f};
  gltf::Quaternion rotation;
  std::int32_t mesh = -1, skin = -1;
  std::vector<double> weights;  // the node's morph weights; empty: the mesh's
};

// The file at one moment: where its nodes are and what they place.
struct GltfPose {
  std::vector<Affine> world;  // per node of the file (the identity for nodes outside the scene)
  std::vector<GltfPlacement> placements;
  std::vector<GltfCamera> cameras;  // in node order
  std::vector<GltfLight> lights;    // in node order
  std::vector<TriangleMesh> deformed;
};

// The file, and (as the GltfPose it derives from) its pose without animation: every node as its
// translation, rotation, scale or matrix say, skins and the meshes' or nodes' morph weights applied.
struct GltfAsset : GltfPose {
  std::filesystem::path file;
  // triangle_materials and `material` index into `materials`; kNoMaterial marks primitives
  // without a material (they take the scene's default).
  std::vector<TriangleMesh> meshes;
  std::vector<MaterialDesc> materials;              // one per glTF material, in file order
  MeshLoadStats stats;                              // summed over all meshes, with the loader's warnings
  std::vector<gltf::MeshDeformation> deformations;  // one per mesh
  std::vector<GltfNode> nodes;                      // every node of the file
  // The nodes in an order that puts parents before children: every node, and then those of the
  // scene rendered (depth first from its roots, the order placements, cameras and lights follow).
  std::vector<std::uint32_t> node_order, scene_nodes;
  std::vector<gltf::Animation> animations;
  std::vector<gltf::Skin> skins;

  bool animated() const { return !animations.empty(); }
  // The mesh a placement of `pose` draws.
  const TriangleMesh& mesh_of(const GltfPose& pose, const GltfPlacement& placement) const {
    return placement.deformed >= 0 ? pose.deformed[std::size_t(placement.deformed)] : meshes[placement.mesh];
  }
  // The world bounds of every mesh placed in `pose` (by default the asset's own); empty when
  // nothing is placed.
  BBox bounds(const GltfPose& pose) const;
  BBox bounds() const { return bounds(*this); }
};

}  // namespace rtpro
