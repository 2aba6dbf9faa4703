#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/render_camera.h"

#include <cmath>
#include <numbers>

namespace rtpro {

RenderCamera make_render_camera(const CameraDesc& desc) {
  RenderCamera c;
  c.position = desc.position;
  c.look_at = desc.look_at;
  c.up = desc.up;
  c.fov_degrees = desc.fov_degrees;
  c.width = desc.width;
  c.height = desc.height;
  c.forward = normalize(desc.look_at - desc.position);
  c.right = normalize(cross(c.forward, desc.up));
  c.true_up = cross(c.right, c.forward);
  c.inv_width = 1.0f / static_cast<float>(desc.width);
  c.inv_height = 1.0f / static_cast<float>(desc.height);
  c.orthographic = desc.projection == CameraProjection::kOrthographic;
  c.half_height = c.orthographic ? 0.5f * desc.ortho_height
                                 : static_cast<float>(std::tan(double(desc.fov_degrees) * std::numbers::pi / 360.0));
  c.half_width = c.half_height * static_cast<float>(desc.width) / static_cast<float>(desc.height);
  // A lens focuses the rays through one point; parallel rays have none to focus (the parser
  // refuses an aperture on an orthographic camera).
  c.lens_radius = c.orthographic ? 0.0f : desc.aperture;
  c.shutter = desc.shutter;
  for (const Affine& step : desc.frame_steps) {
    CameraPose pose;
    pose.position = Vec3(step.m[0][3], step.m[1][3], step.m[2][3]);
    pose.forward = normalize(Vec3(step.m[0][2], step.m[1][2], step.m[2][2]));
    pose.right = normalize(cross(pose.forward, Vec3(step.m[0][1], step.m[1][1], step.m[2][1])));
    pose.true_up = cross(pose.right, pose.forward);
    c.pose_steps.push_back(pose);
  }
  c.focus_distance = desc.focus_distance > 0.0f ? desc.focus_distance : length(desc.look_at - desc.position);
  return c;
}

CameraPose camera_pose_at(const RenderCamera& camera, float time) {
  if (!camera.moving()) return camera.pose();
  const MotionSegment segment = motion_segment(time, camera.pose_steps.size());
  const CameraPose& a = camera.pose_steps[segment.index];
  const CameraPose& b = camera.pose_steps[segment.index + 1];
  const float t = segment.fraction;
  CameraPose pose;
  pose.position = motion_lerp(a.position, b.position, t);
  pose.forward = normalize(motion_lerp(a.forward, b.forward, t));
  pose.right = normalize(cross(pose.forward, motion_lerp(a.true_up, b.true_up, t)));
  pose.true_up = cross(pose.right, pose.forward);
  return pose;
}

void set_pose(RenderCamera& camera, const CameraPose& pose) {
  camera.position = pose.position;
  camera.forward = pose.forward;
  camera.right = pose.right;
  camera.true_up = pose.true_up;
}

std::optional<FilmPoint> film_point(const RenderCamera& camera, const CameraPose& pose, const Vec3& p) {
  const Vec3 d = p - pose.position;
  const float depth = dot(d, pose.forward);
  if (!(depth > 0.0f)) return std::nullopt;
  // The point's offset on the image plane (at distance 1 in perspective), in half extents of the image.
  const float scale = camera.orthographic ? 1.0f : depth;
  const float x = dot(d, pose.right) / scale / camera.half_width;
  const float y = dot(d, pose.true_up) / scale / camera.half_height;
  return FilmPoint{(x + 1.0f) * 0.5f * static_cast<float>(camera.width),
                   (1.0f - y) * 0.5f * static_cast<float>(camera.height)};
}

}  // namespace rtpro
