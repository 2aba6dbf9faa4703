#include "subdivision_level.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

constexpr float kPi = 3.14159265358979323846f;

}  // namespace

int choose_subdivision_level(const PolygonCage& cage, const CameraDesc& camera, float edge_length, int cap) {
  // A pixel's width at distance 1 (perspective), or anywhere (orthographic).
  const bool orthographic = camera.projection == CameraProjection::kOrthographic;
  const float pixel_angle = orthographic ? camera.ortho_height / float(camera.height)
                                         : 2.0f * std::tan(camera.fov_degrees * kPi / 360.0f) / float(camera.height);
  float longest = 0.0f;  // pixels
  std::size_t first = 0;
  for (std::size_t f = 0; f < cage.face_count(); first += cage.face_sizes[f], ++f) {
    const std::uint32_t n = cage.face_sizes[f];
    for (std::uint32_t k = 0; k < n; ++k) {
      const Vec3 a = cage.positions[cage.face_vertices[first + k]];
      const Vec3 b = cage.positions[cage.face_vertices[first + (k + 1) % n]];
      const float length_ab = length(b - a);
      const float z =
          orthographic
              ? 1.0f
              : std::max({std::min(length(a - camera.position), length(b - camera.position)), length_ab, 1e-30f});
      longest = std::max(longest, length_ab / (z * pixel_angle));
    }
  }
  if (!(longest > edge_length)) return 0;
  return std::clamp(int(std::ceil(std::log2(longest / edge_length))), 0, cap);
}

}  // namespace rtpro
