#pragma once
// Pinhole camera. Right-handed world, +y up by convention: the image's +x runs along
// cross(forward, up). Pixel coordinates are continuous, (0,0) at the top-left corner.
#include "rtpro/core/ray.h"
#include "rtpro/scene/description.h"

namespace rtpro {

class Camera {
 public:
  Camera(const CameraDesc& desc, int width, int height);
  Ray generate(float px, float py) const;

 private:
  Vec3 origin_, forward_, right_, up_;
  float half_width_, half_height_;  // of the image plane at distance 1
  float inv_width_, inv_height_;
};

}  // namespace rtpro
