#include "rtpro/render/camera.h"

namespace rtpro {

Ray camera_ray(const RenderCamera& camera, float px, float py) {
  const float x = (2.0f * px * camera.inv_width - 1.0f) * camera.half_width;
  const float y = (1.0f - 2.0f * py * camera.inv_height) * camera.half_height;
  Ray ray;
  ray.org = camera.position;
  ray.dir = normalize(camera.forward + camera.right * x + camera.true_up * y);
  return ray;
}

}  // namespace rtpro
