#pragma once
// Camera rays from the render scene's pinhole camera. Pixel coordinates are continuous, (0,0) at
// the image's top-left corner; the film point comes from the sampler's pixel dimensions.
#include "rtpro/core/ray.h"
#include "rtpro/scene/render_camera.h"

namespace rtpro {

Ray camera_ray(const RenderCamera& camera, float px, float py);

}  // namespace rtpro
