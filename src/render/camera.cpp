#include "rtpro/render/camera.h"

#include <cmath>
#include <numbers>

namespace rtpro {

Camera::Camera(const CameraDesc& desc, int width, int height)
    : origin_(desc.position),
      forward_(normalize(desc.look_at - desc.position)),
      right_(normalize(cross(forward_, desc.up))),
      up_(cross(right_, forward_)),
      inv_width_(1.0f / static_cast<float>(width)),
      inv_height_(1.0f / static_cast<float>(height)) {
  half_height_ = static_cast<float>(std::tan(double(desc.fov_degrees) * std::numbers::pi / 360.0));
  half_width_ = half_height_ * static_cast<float>(width) / static_cast<float>(height);
}

Ray Camera::generate(float px, float py) const {
  const float x = (2.0f * px * inv_width_ - 1.0f) * half_width_;
  const float y = (1.0f - 2.0f * py * inv_height_) * half_height_;
  Ray ray;
  ray.org = origin_;
  ray.dir = normalize(forward_ + right_ * x + up_ * y);
  return ray;
}

}  // namespace rtpro
