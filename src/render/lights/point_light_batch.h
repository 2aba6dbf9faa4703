#pragma once
// A point light's samples (sample_point_light) from many surface points, four at a time in SSE2
// registers. One sample is a latency chain (a square root, then a division by it and another by
// its square, then the products), so the path integrator's vertices lit by one point light wait on
// it one after another; lanes run four chains side by side. Each lane is sample_point_light's
// arithmetic, operation for operation: the same samples bit for bit.
#include "path_light.h"
#include "surface.h"
#include "rtpro/scene/light.h"

#include <cstdint>
#include <span>

namespace rtpro {

// For every i: found[i] = sample_point_light(light, points[i].position, out[i]); out[i] is
// written in full (a point at the light gives found 0 and an unspecified sample).
void sample_point_light_batch(const PointLight& light, std::span<const SurfacePoint> points,
                              std::span<PathLightSample> out, std::span<std::uint8_t> found);

}  // namespace rtpro
