#include "gltf_motion.h"

#include "gltf_pose.h"
#include "rtpro/scene/render_camera.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rtpro {

namespace {

// Node states by time in frames: the steps of every placement fall on the same few times.
class StatesOverShutter {
 public:
  StatesOverShutter(const GltfAsset& asset, double fps) : asset_(asset), fps_(fps) {}

  const gltf::NodeState& at(double frame) {
    auto found = states_.find(frame);
    if (found == states_.end()) found = states_.emplace(frame, gltf::animate_nodes(asset_, frame / fps_)).first;
    return found->second;
  }

 private:
  const GltfAsset& asset_;
  double fps_;
  std::map<double, gltf::NodeState> states_;
};

bool vertices_equal(const VertexArray& a, const VertexArray& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const MeshVertex& p, const MeshVertex& q) { return p.x == q.x && p.y == q.y && p.z == q.z; });
}

// Whether every vertex of `middle` lies within `tolerance` (per coordinate) of the midpoint of its
// positions in `before` and `after`, computed as the backends interpolate.
bool on_chords(const VertexArray& before, const VertexArray& middle, const VertexArray& after, double tolerance) {
  for (std::size_t i = 0; i < middle.size(); ++i) {
    const Vec3 chord = motion_lerp(before[i].position(), after[i].position(), 0.5f);
    const Vec3 d = middle[i].position() - chord;
    if (std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)}) > tolerance) return false;
  }
  return true;
}

// The mesh of `placement` posed at time steps over the shutter, as few as kMaxDeformationSteps's
// rule allows (gltf_motion.h); its steps stay empty when it keeps still.
void add_vertex_steps(const GltfAsset& asset, const GltfPlacement& placement, const Shutter& shutter, double frame,
                      StatesOverShutter& states, TriangleMesh& mesh) {
  const GltfNode& node = asset.nodes[placement.node];
  const gltf::MeshDeformation& deformation = asset.deformations[placement.mesh];
  const bool skinned = node.skin >= 0 && deformation.skinned();
  const auto pose_at = [&](double time) {
    const gltf::NodeState& state = states.at(time);
    std::vector<Affine> joints;
    if (skinned) joints = gltf::joint_matrices(asset.skins[std::size_t(node.skin)], state.world);
    return gltf::deform_mesh(asset.meshes[placement.mesh], deformation, state.weights[placement.node],
                             skinned ? &joints : nullptr, asset.file.string(), gltf_node_path(placement.node));
  };
  std::vector<TriangleMesh> steps;
  for (const double time : motion_step_times(shutter, frame, 2)) steps.push_back(pose_at(time));
  const double tolerance = kMotionChordTolerance * static_cast<double>(length(steps.front().bounds().extent()));
  while (static_cast<int>(steps.size()) < kMaxDeformationSteps) {
    // The finer steps' times, from motion_step_times itself: the steps of every count fall on them.
    const std::vector<double> finer = motion_step_times(shutter, frame, 2 * static_cast<int>(steps.size()) - 1);
    std::vector<TriangleMesh> middles;
    bool close_enough = true;
    for (std::size_t i = 0; i + 1 < steps.size(); ++i) {
      middles.push_back(pose_at(finer[2 * i + 1]));
      close_enough =
          close_enough && on_chords(steps[i].vertices, middles.back().vertices, steps[i + 1].vertices, tolerance);
    }
    if (close_enough) break;
    std::vector<TriangleMesh> refined;
    for (std::size_t i = 0; i < middles.size(); ++i) {
      refined.push_back(std::move(steps[i]));
      refined.push_back(std::move(middles[i]));
    }
    refined.push_back(std::move(steps.back()));
    steps = std::move(refined);
  }
  for (TriangleMesh& posed : steps) {
    mesh.vertex_steps.push_back(std::move(posed.vertices));
    if (!mesh.normals.empty()) mesh.normal_steps.push_back(std::move(posed.normals));
  }
  const auto& vertex_steps = mesh.vertex_steps;
  if (std::all_of(vertex_steps.begin(), vertex_steps.end(),
                  [&](const auto& s) { return vertices_equal(s, vertex_steps.front()); })) {
    mesh.vertex_steps.clear();
    mesh.normal_steps.clear();
  }
}

}  // namespace

GltfPose pose_gltf_frame(const GltfAsset& asset, double frame, double fps, const Shutter& shutter) {
  GltfPose pose = pose_gltf(asset, frame / fps);
  if (!asset.animated() || !shutter.is_open()) return pose;
  StatesOverShutter states(asset, fps);
  for (GltfPlacement& placement : pose.placements) {
    const GltfNode& node = asset.nodes[placement.node];
    const gltf::MeshDeformation& deformation = asset.deformations[placement.mesh];
    const bool skinned = node.skin >= 0 && deformation.skinned();
    if (!skinned)
      placement.transform_steps =
          sample_transform_motion(shutter, frame, [&](double time) { return states.at(time).world[placement.node]; });
    if (!skinned && !deformation.morphs()) continue;
    // A morphed mesh whose weights are all 0 at the frame may still move during the shutter.
    if (placement.deformed < 0) {
      pose.deformed.push_back(asset.meshes[placement.mesh]);
      placement.deformed = std::int32_t(pose.deformed.size() - 1);
    }
    add_vertex_steps(asset, placement, shutter, frame, states, pose.deformed[std::size_t(placement.deformed)]);
  }
  return pose;
}

std::vector<Affine> gltf_camera_frame_steps(const GltfAsset& asset, const GltfCamera& camera, double frame, double fps,
                                            const Shutter& shutter) {
  if (!asset.animated()) return {};
  return sample_transform_motion(shutter, frame, [&](double at) {
    GltfCamera placed = camera;
    // A step whose node leaves no view direction keeps the file's rest placement.
    gltf::place_camera(placed, gltf::animate_nodes(asset, at / fps).world[camera.node]);
    return camera_frame(placed.position, placed.forward, placed.up);
  });
}

}  // namespace rtpro
