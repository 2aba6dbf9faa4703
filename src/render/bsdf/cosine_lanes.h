#pragma once
// Cosine-weighted hemisphere directions for many samples, four at a time in SSE2 registers: the
// Lambert sample of each path vertex of a generation, worked out before the vertices are shaded.
// One sample's chain (a division, a polynomial, a square root, and a branch on the disk's wedge
// that mispredicts half the time) is latency; lanes run four chains side by side. Each lane is
// sample_cosine_hemisphere's arithmetic, operation for operation (the branch a select): the
// same directions bit for bit.
#include "bsdf_sample.h"

#include <cstddef>

namespace rtpro {

// out_i = sample_cosine_hemisphere(u_i) for i < count, where u_i and out_i are `stride` bytes
// apart (fields of an array of records).
void sample_cosine_hemispheres(std::size_t count, const Sample2D* u, Vec3* out, std::size_t stride);

}  // namespace rtpro
