#pragma once
// One sphere against the rays of an Embree packet, several rays at a time: the answer of
// rtpro::intersect_sphere for every lane, bit for bit. The lanes compute in double with the very
// operations of the scalar function, in its order (IEEE add, multiply, divide and square root are
// exact per lane whatever the vector width; no contraction into fused multiply-adds), so a sphere
// hit does not depend on whether it came through a packet, a single ray or the native backend.
//
// AVX2 (four doubles) where the CPU has it, chosen once at run time; otherwise the scalar function
// lane by lane. (An AVX-512 path, eight doubles, was 3% faster on an AMD EPYC and 6-8% slower on
// an Intel Xeon with AVX-512, measured on many_spheres and the demo: it is not kept.)
#include "rtpro/core/vec3.h"

#include <cstdint>

namespace rtpro {

// The rays of a packet as Embree lays them out: one array per field, `count` lanes each.
struct RayLanes {
  const float* org_x;
  const float* org_y;
  const float* org_z;
  const float* dir_x;
  const float* dir_y;
  const float* dir_z;
  const float* tnear;
  const float* tfar;
  unsigned count;  // at most 32
};

// For each lane i with bit i of `active` set: whether intersect_sphere(center, radius, org, dir,
// tnear, tfar, t) is true, as bit i of the result, and its t in t_hit[i]. Other lanes of t_hit are
// left as they were.
std::uint32_t intersect_sphere_lanes(const Vec3& center, float radius, const RayLanes& rays, std::uint32_t active,
                                     float* t_hit);

// Whether the vector path is in use on this CPU (for tests and statistics).
bool sphere_lanes_vectorised();

}  // namespace rtpro
