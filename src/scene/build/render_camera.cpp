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
  c.half_height = static_cast<float>(std::tan(double(desc.fov_degrees) * std::numbers::pi / 360.0));
  c.half_width = c.half_height * static_cast<float>(desc.width) / static_cast<float>(desc.height);
  c.lens_radius = desc.aperture;
  c.shutter = desc.shutter;
  c.focus_distance = desc.focus_distance > 0.0f ? desc.focus_distance : length(desc.look_at - desc.position);
  return c;
}

}  // namespace rtpro
