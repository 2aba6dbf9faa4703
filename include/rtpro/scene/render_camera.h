#pragma once
// The camera as the renderer uses it: the scene file's camera (a pinhole, a thin lens with an
// aperture, or an orthographic view) with its frame worked out once. Right-handed world, +y up by
// convention: the image's +x runs along cross(forward, up); pixel coordinates are continuous,
// (0,0) at the top-left corner.
#include "rtpro/core/vec3.h"
#include "rtpro/scene/motion.h"

#include <optional>
#include <vector>

namespace rtpro {

// Where the camera stands and which way it looks: unit forward, right and up vectors.
struct CameraPose {
  Vec3 position, forward, right, true_up;
};

// A camera's frame as a transform (the steps a moving camera keeps, CameraDesc::frame_steps): its
// columns the unit right, up and forward vectors of a camera at `position` looking along
// `forward` with `up` above, its translation the position.
inline Affine camera_frame(const Vec3& position, const Vec3& forward, const Vec3& up) {
  const Vec3 f = normalize(forward);
  const Vec3 right = normalize(cross(f, up));
  const Vec3 columns[4] = {right, cross(right, f), f, position};
  Affine frame;
  for (std::size_t c = 0; c < 4; ++c) {
    frame.m[0][c] = columns[c].x;
    frame.m[1][c] = columns[c].y;
    frame.m[2][c] = columns[c].z;
  }
  return frame;
}

struct RenderCamera {
  // As the scene file gave them (for reports).
  Vec3 position, look_at, up;
  float fov_degrees = 45.0f;
  int width = 0, height = 0;

  // The frame rays are generated in: unit forward, right and up vectors, and the half extent of
  // the image plane at distance 1 (orthographic: of the view, in scene units, whose rays leave the
  // plane through `position` along `forward`).
  bool orthographic = false;
  Vec3 forward, right, true_up;
  float half_width = 0.0f, half_height = 0.0f;
  float inv_width = 0.0f, inv_height = 0.0f;

  // Thin lens: radius in scene units (0: pinhole) and the focus distance along `forward`.
  float lens_radius = 0.0f;
  float focus_distance = 1.0f;

  // The exposure (scene/motion.h); while open, each camera sample gets a time in it.
  Shutter shutter;
  // A moving camera's poses at the shutter's time steps (scene/motion.h); empty when it stands
  // still. position, forward, right and true_up above stay the pose at the frame's time.
  std::vector<CameraPose> pose_steps;

  bool moving() const { return !pose_steps.empty(); }
  CameraPose pose() const { return {position, forward, right, true_up}; }
};

// The camera's pose at ray time `time` in [0, 1]: between steps the position moves linearly and
// the frame turns along the interpolated forward and up vectors, made orthonormal again.
CameraPose camera_pose_at(const RenderCamera& camera, float time);
void set_pose(RenderCamera& camera, const CameraPose& pose);

// A point on the film in continuous pixel coordinates ((0,0) the top-left corner, +y down).
struct FilmPoint {
  float x = 0.0f, y = 0.0f;
};
// Where world point `p` lands on the film of `camera` standing at `pose`: camera_ray's inverse
// (for the thin lens, the image of its centre). Nothing for a point behind the camera.
std::optional<FilmPoint> film_point(const RenderCamera& camera, const CameraPose& pose, const Vec3& p);

}  // namespace rtpro
