#include "rtpro/render/camera.h"

#include <cmath>
#include <numbers>

namespace rtpro {

Sample2D concentric_disk(Sample2D square) {
  const float u = 2.0f * square.x - 1.0f, v = 2.0f * square.y - 1.0f;
  if (u == 0.0f && v == 0.0f) return {0.0f, 0.0f};
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.0f;
  const bool wide = std::fabs(u) > std::fabs(v);
  const float radius = wide ? u : v;
  const float angle = wide ? kQuarterPi * (v / u) : 2.0f * kQuarterPi - kQuarterPi * (u / v);
  return {radius * std::cos(angle), radius * std::sin(angle)};
}

}  // namespace rtpro
