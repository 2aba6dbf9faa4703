#include "gltf_pose.h"

#include <algorithm>
#include <array>

namespace rtpro {

namespace gltf {

Affine local_transform(const Vec3& translation, const Quaternion& rotation, const Vec3& scale) {
  return compose(Affine::translate(translation), compose(rotation_matrix(rotation), Affine::scale(scale)));
}

std::vector<Affine> node_locals(const std::vector<GltfNode>& nodes) {
  std::vector<Affine> locals;
  locals.reserve(nodes.size());
  for (const GltfNode& n : nodes)
    locals.push_back(n.matrix ? *n.matrix : local_transform(n.translation, n.rotation, n.scale));
  return locals;
}

std::vector<Affine> node_worlds(const GltfAsset& asset, const std::vector<Affine>& locals) {
  std::vector<Affine> world(asset.nodes.size());
  for (const std::uint32_t n : asset.node_order) {
    const std::uint32_t parent = asset.nodes[n].parent;
    world[n] = parent == GltfNode::kNoParent ? locals[n] : compose(world[parent], locals[n]);
  }
  return world;
}

std::vector<std::vector<double>> rest_weights(const GltfAsset& asset) {
  std::vector<std::vector<double>> weights(asset.nodes.size());
  for (std::size_t n = 0; n < asset.nodes.size(); ++n) {
    const GltfNode& node = asset.nodes[n];
    if (node.mesh < 0 || !asset.deformations[std::size_t(node.mesh)].morphs()) continue;
    weights[n] = node.weights.empty() ? asset.deformations[std::size_t(node.mesh)].default_weights : node.weights;
  }
  return weights;
}

std::size_t place_meshes(const GltfAsset& asset, const std::vector<std::vector<double>>& weights, GltfPose& pose) {
  pose.placements.clear();
  pose.deformed.clear();
  std::size_t singular = 0;
  for (const std::uint32_t n : asset.scene_nodes) {
    const GltfNode& node = asset.nodes[n];
    if (node.mesh < 0) continue;
    const auto mesh = std::size_t(node.mesh);
    const MeshDeformation& deformation = asset.deformations[mesh];
    const bool skinned = node.skin >= 0 && deformation.skinned();
    const bool morphed = std::any_of(weights[n].begin(), weights[n].end(), [](double w) { return w != 0.0; });
    // A skinned mesh is placed by its joints alone: the node's own transform does not count.
    if (!skinned && !inverse(pose.world[n])) {
      ++singular;
      continue;
    }
    GltfPlacement placement{std::uint32_t(mesh), n, skinned ? Affine::identity() : pose.world[n]};
    if (skinned || morphed) {
      std::vector<Affine> joints;
      if (skinned) joints = joint_matrices(asset.skins[std::size_t(node.skin)], pose.world);
      pose.deformed.push_back(deform_mesh(asset.meshes[mesh], deformation, weights[n], skinned ? &joints : nullptr,
                                          asset.file.string(), gltf_node_path(n)));
      placement.deformed = std::int32_t(pose.deformed.size() - 1);
    }
    pose.placements.push_back(placement);
  }
  return singular;
}

bool place_camera(GltfCamera& camera, const Affine& world) {
  const Vec3 forward = world.apply_vector(Vec3(0, 0, -1)), up = world.apply_vector(Vec3(0, 1, 0));
  if (!(length(forward) > 0.0f) || !(length(cross(forward, up)) > 0.0f)) return false;
  camera.position = world.apply_point(Vec3(0, 0, 0));
  camera.forward = normalize(forward);
  camera.up = normalize(up);
  return true;
}

void place_light(GltfLight& light, const Affine& world) {
  light.position = world.apply_point(Vec3(0, 0, 0));
  const Vec3 direction = world.apply_vector(Vec3(0, 0, -1));
  light.direction = length(direction) > 0.0f ? normalize(direction) : Vec3(0, -1, 0);
}

NodeState animate_nodes(const GltfAsset& asset, double seconds) {
  const std::size_t count = asset.nodes.size();
  std::vector<Vec3> translation(count), scale(count);
  std::vector<Quaternion> rotation(count);
  for (std::size_t n = 0; n < count; ++n) {
    translation[n] = asset.nodes[n].translation;
    rotation[n] = asset.nodes[n].rotation;
    scale[n] = asset.nodes[n].scale;
  }
  NodeState state{{}, rest_weights(asset)};
  // Each node follows the first animation with a channel for it (gltf_pose.h).
  std::vector<std::size_t> animation_of(count, asset.animations.size());
  for (std::size_t a = 0; a < asset.animations.size(); ++a)
    for (const AnimationChannel& c : asset.animations[a].channels)
      animation_of[c.node] = std::min(animation_of[c.node], a);
  for (std::size_t a = 0; a < asset.animations.size(); ++a) {
    const Animation& animation = asset.animations[a];
    for (const AnimationChannel& c : animation.channels) {
      if (animation_of[c.node] != a) continue;
      const AnimationSampler& sampler = animation.samplers[c.sampler];
      std::vector<double> value(sampler.width);
      sample(sampler, seconds, c.path == AnimatedPath::kRotation, value);
      switch (c.path) {
        case AnimatedPath::kTranslation:
          translation[c.node] = Vec3(float(value[0]), float(value[1]), float(value[2]));
          break;
        case AnimatedPath::kRotation: rotation[c.node] = {value[0], value[1], value[2], value[3]}; break;
        case AnimatedPath::kScale: scale[c.node] = Vec3(float(value[0]), float(value[1]), float(value[2])); break;
        case AnimatedPath::kWeights: state.weights[c.node] = std::move(value); break;
      }
    }
  }
  std::vector<Affine> locals(count);
  for (std::size_t n = 0; n < count; ++n) {
    const GltfNode& node = asset.nodes[n];
    locals[n] = node.matrix ? *node.matrix : local_transform(translation[n], rotation[n], scale[n]);
  }
  state.world = node_worlds(asset, locals);
  return state;
}

}  // namespace gltf

GltfPose pose_gltf(const GltfAsset& asset, double seconds) {
  if (!asset.animated()) return asset;
  gltf::NodeState state = gltf::animate_nodes(asset, seconds);
  GltfPose pose;
  pose.world = std::move(state.world);
  gltf::place_meshes(asset, state.weights, pose);
  pose.cameras = asset.cameras;
  for (GltfCamera& camera : pose.cameras) gltf::place_camera(camera, pose.world[camera.node]);
  pose.lights = asset.lights;
  for (GltfLight& light : pose.lights) gltf::place_light(light, pose.world[light.node]);
  return pose;
}

}  // namespace rtpro
