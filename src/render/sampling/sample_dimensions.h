#pragma once
// Which sampler dimensions each random decision of a camera sample uses. Fixed numbers, not a
// counter advanced as the code runs: a decision draws the same value however many others were
// made before it, so adding a feature never reshuffles the noise of the ones that exist.
namespace rtpro::sample_dimension {

inline constexpr int kPixel = 0;  // and 1: the position inside the pixel
inline constexpr int kLens = 2;   // and 3: the point on the lens (thin-lens depth of field)
// The sample's time in the shutter (scene/motion.h), drawn only while it is open: far past any
// bounce's dimensions, so the images of an instant shutter keep every other dimension's values.
inline constexpr int kTime = 1 << 24;
// Decisions made at the k-th surface a sample's rays reach (k = 0 for the camera ray's hit) use
// dimensions kFirstBounce + k · kPerBounce + offset, offset < kPerBounce.
inline constexpr int kFirstBounce = 4;
inline constexpr int kPerBounce = 8;

constexpr int at_bounce(int bounce, int offset) { return kFirstBounce + bounce * kPerBounce + offset; }

}  // namespace rtpro::sample_dimension
