#include "rtpro/core/transform.h"

#include <cmath>
#include <numbers>

namespace rtpro {

Affine Affine::translate(const Vec3& t) {
  Affine a;
  a.m[0][3] = t.x;
  a.m[1][3] = t.y;
  a.m[2][3] = t.z;
  return a;
}

Affine Affine::scale(const Vec3& s) {
  Affine a;
  a.m[0][0] = s.x;
  a.m[1][1] = s.y;
  a.m[2][2] = s.z;
  return a;
}

Affine Affine::rotate(const Vec3& axis, float angle_degrees) {
  // Rodrigues' formula in double so that 90° steps come out exact after rounding.
  const double len = std::sqrt(double(axis.x) * axis.x + double(axis.y) * axis.y + double(axis.z) * axis.z);
  const double x = axis.x / len, y = axis.y / len, z = axis.z / len;
  const double theta = double(angle_degrees) * std::numbers::pi / 180.0;
  const double c = std::cos(theta), s = std::sin(theta), t = 1.0 - c;
  const double r[3][3] = {{t * x * x + c, t * x * y - s * z, t * x * z + s * y},
                          {t * x * y + s * z, t * y * y + c, t * y * z - s * x},
                          {t * x * z - s * y, t * y * z + s * x, t * z * z + c}};
  Affine a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a.m[i][j] = static_cast<float>(r[i][j]);
  return a;
}

Vec3 Affine::apply_point(const Vec3& p) const {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

Vec3 Affine::apply_vector(const Vec3& v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3 Affine::apply_normal_of_inverse(const Vec3& n) const {
  // (M⁻¹)ᵀ·n, with `this` already being M⁻¹: multiply by the transpose of the linear part.
  return {m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
          m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z};
}

BBox Affine::apply(const BBox& b) const {
  BBox out;
  if (b.empty()) return out;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p{(corner & 1) ? b.upper.x : b.lower.x, (corner & 2) ? b.upper.y : b.lower.y,
                 (corner & 4) ? b.upper.z : b.lower.z};
    out.extend(apply_point(p));
  }
  return out;
}

bool Affine::is_finite() const {
  for (const auto& row : m)
    for (float v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

float Affine::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Affine compose(const Affine& a, const Affine& b) {
  Affine out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = (j == 3) ? a.m[i][3] : 0.0;
      for (int k = 0; k < 3; ++k) sum += double(a.m[i][k]) * b.m[k][j];
      out.m[i][j] = static_cast<float>(sum);
    }
  }
  return out;
}

std::optional<Affine> inverse(const Affine& a) {
  double l[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l[i][j] = a.m[i][j];
  const double det = l[0][0] * (l[1][1] * l[2][2] - l[1][2] * l[2][1]) -
                     l[0][1] * (l[1][0] * l[2][2] - l[1][2] * l[2][0]) +
                     l[0][2] * (l[1][0] * l[2][1] - l[1][1] * l[2][0]);
  double scale = 0.0;
  for (const auto& row : l)
    for (double v : row) scale = std::max(scale, std::fabs(v));
  // Singular, or so ill-conditioned that the inverse would be meaningless in float.
  if (!std::isfinite(det) || scale == 0.0 || std::fabs(det) <= 1e-12 * scale * scale * scale) return std::nullopt;

  double inv[3][3];
  inv[0][0] = (l[1][1] * l[2][2] - l[1][2] * l[2][1]) / det;
  inv[0][1] = (l[0][2] * l[2][1] - l[0][1] * l[2][2]) / det;
  inv[0][2] = (l[0][1] * l[1][2] - l[0][2] * l[1][1]) / det;
  inv[1][0] = (l[1][2] * l[2][0] - l[1][0] * l[2][2]) / det;
  inv[1][1] = (l[0][0] * l[2][2] - l[0][2] * l[2][0]) / det;
  inv[1][2] = (l[0][2] * l[1][0] - l[0][0] * l[1][2]) / det;
  inv[2][0] = (l[1][0] * l[2][1] - l[1][1] * l[2][0]) / det;
  inv[2][1] = (l[0][1] * l[2][0] - l[0][0] * l[2][1]) / det;
  inv[2][2] = (l[0][0] * l[1][1] - l[0][1] * l[1][0]) / det;

  Affine out;
  for (int i = 0; i < 3; ++i) {
    double t = 0.0;
    for (int k = 0; k < 3; ++k) t -= inv[i][k] * a.m[k][3];
    for (int j = 0; j < 3; ++j) out.m[i][j] = static_cast<float>(inv[i][j]);
    out.m[i][3] = static_cast<float>(t);
  }
  if (!out.is_finite()) return std::nullopt;
  return out;
}

}  // namespace rtpro
