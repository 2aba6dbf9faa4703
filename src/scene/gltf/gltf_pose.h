#pragma once
// A glTF file posed at a moment of its animation: each node's translation, rotation, scale and
// morph weights from the animation that keys it (gltf_animation.h), the world transforms that
// follow down the hierarchy, and from them the placements of meshes (skinned and morphed ones
// deformed: gltf_deformation.h), cameras and lights.
//
// Several animations: each node follows the first animation (in file order) that has a channel
// for it, and is left as the file places it by the others, as Blender's importer makes the
// first action that animates an object the active one. Channels an animation lacks leave that
// part of the node as the file places it.
#include "gltf_asset.h"

#include <vector>

namespace rtpro {

// The asset at `seconds` into its animation; the asset's own pose for a file without animations.
GltfPose pose_gltf(const GltfAsset& asset, double seconds);

namespace gltf {

// Every node's world transform and morph weights (empty for nodes without targets) at `seconds`.
struct NodeState {
  std::vector<Affine> world;
  std::vector<std::vector<double>> weights;
};
NodeState animate_nodes(const GltfAsset& asset, double seconds);

// The loader's parts of posing (the asset's pose without animation).
Affine local_transform(const Vec3& translation, const Quaternion& rotation, const Vec3& scale);
std::vector<Affine> node_locals(const std::vector<GltfNode>& nodes);
std::vector<Affine> node_worlds(const GltfAsset& asset, const std::vector<Affine>& locals);
// Per node: its own morph weights, else its mesh's (empty for nodes without morph targets).
std::vector<std::vector<double>> rest_weights(const GltfAsset& asset);
// Fills pose.placements (and pose.deformed) from pose.world for the scene's nodes that draw a
// mesh, with each node's morph `weights`; returns how many nodes a singular transform hides.
std::size_t place_meshes(const GltfAsset& asset, const std::vector<std::vector<double>>& weights, GltfPose& pose);
// A camera or light where `world` puts its node; place_camera is false (and leaves `camera` as it
// was) when `world` leaves no usable view direction.
bool place_camera(GltfCamera& camera, const Affine& world);
void place_light(GltfLight& light, const Affine& world);

}  // namespace gltf

}  // namespace rtpro
