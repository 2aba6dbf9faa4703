#pragma once
// A glTF animation over a frame's exposure (scene/motion.h): the pose at the frame, with the time
// steps that motion blur interpolates between.
// - A placement whose node moves during the shutter gets transform steps, as many as keep a
//   rotation on its arc (sample_transform_motion).
// - A skinned or morphed mesh whose vertices move gets vertex steps (normal steps too when it has
//   normals), as few as keep it on its path (kMaxDeformationSteps); its placement, for a skinned
//   mesh the identity, keeps still.
// Nothing gets steps with a closed shutter or a file without animations.
#include "gltf_asset.h"
#include "rtpro/scene/motion.h"

namespace rtpro {

// Vertex steps of a deforming mesh: 2, 3, 5 or 9, doubling the segments until every segment's
// midpoint pose lies within kMotionChordTolerance of the mesh's size of the segment's linear
// interpolation (a morph whose weights change linearly in the shutter takes 2: its vertices move
// on straight lines), at most kMaxDeformationSteps. Each step is a whole copy of the vertices, and
// every segment costs the backends' motion BVHs nodes, so the count stays small: 8 segments keep
// a joint turning a quarter turn within 2% of its radius of its arc.
inline constexpr int kMaxDeformationSteps = 9;

// The pose at frame `frame` (frame / fps seconds) with the steps of `shutter` (in frames).
GltfPose pose_gltf_frame(const GltfAsset& asset, double frame, double fps, const Shutter& shutter);

// The frame of `camera` (camera_frame, scene/render_camera.h) at the steps of `shutter` around
// frame `frame`, as many as keep a turn on its arc; empty when its node keeps still.
std::vector<Affine> gltf_camera_frame_steps(const GltfAsset& asset, const GltfCamera& camera, double frame, double fps,
                                            const Shutter& shutter);

}  // namespace rtpro
