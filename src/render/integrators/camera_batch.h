#pragma once
// A batch of camera samples, as every integrator traces them: rays[i] is the camera ray of the
// sample keys[i] names (whose random numbers the integrator draws with that key), and results[i]
// receives its radiance and primary hit.
#include "rtpro/core/ray.h"
#include "rtpro/render/sample_result.h"
#include "rtpro/render/sampler.h"

#include <span>

namespace rtpro {

struct CameraBatch {
  std::span<const Ray> rays;
  std::span<const SampleKey> keys;
  std::span<SampleResult> results;
  // Per sample, its time in the shutter (scene/motion.h), which every ray of its path keeps;
  // empty while the shutter is closed.
  std::span<const float> times = {};
};

}  // namespace rtpro
