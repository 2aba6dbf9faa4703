#pragma once
// π and its reciprocal as the float constants the shading code uses.
#include <numbers>

namespace rtpro {

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;

}  // namespace rtpro
