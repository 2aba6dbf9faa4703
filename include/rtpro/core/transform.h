#pragma once
// Affine transforms (3×4 matrices): object-to-world placement of instances.
#include "rtpro/core/bbox.h"
#include "rtpro/core/vec3.h"

#include <array>
#include <optional>

namespace rtpro {

struct Affine {
  // Row-major 3×4: m[r][0..2] is the linear part, m[r][3] the translation.
  std::array<std::array<float, 4>, 3> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

  static Affine identity() { return {}; }
  static Affine translate(const Vec3& t);
  static Affine scale(const Vec3& s);
  // Rotation by angle_degrees about axis (right-handed); axis need not be unit length.
  static Affine rotate(const Vec3& axis, float angle_degrees);

  Vec3 apply_point(const Vec3& p) const;
  Vec3 apply_vector(const Vec3& v) const;
  // Transforms a normal with the inverse transpose of the linear part; `this` must be the
  // world-to-object matrix (the inverse of the placement), so no inverse is computed per call.
  Vec3 apply_normal_of_inverse(const Vec3& n) const;

  BBox apply(const BBox& b) const;
  bool is_finite() const;
  float determinant() const;
  bool operator==(const Affine&) const = default;
};

// a ∘ b: applies b first, then a.
Affine compose(const Affine& a, const Affine& b);
// Inverse, or nothing when the matrix is singular or ill-conditioned.
std::optional<Affine> inverse(const Affine& a);

}  // namespace rtpro
