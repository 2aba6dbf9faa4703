#include "normal_map.h"

#include "texture.h"

#include <cmath>

namespace rtpro {

Vec3 mapped_normal(const NormalMap& map, const SurfacePoint& point, const TextureLookup* textures) {
  const Vec3 n = point.shading_normal;
  const Vec3 tangent = point.tangent - n * dot(n, point.tangent);
  const float tangent_length = length(tangent);
  if (!(tangent_length > 0.0f) || !std::isfinite(tangent_length)) return n;
  const Vec3 t = tangent / tangent_length;
  // The map is defined on the outside, where the bitangent is outside normal × tangent; seen from
  // the inside the normal is flipped, and with it the cross product.
  const float side = point.front_face ? 1.0f : -1.0f;
  const Vec3 b = cross(n, t) * point.bitangent_sign;
  const Color texel = evaluate(ImageTexture{map.image, Color(1.0f), map.sampling}, point.tex_u, point.tex_v, textures);
  const float x = (2.0f * texel.x - 1.0f) * map.scale, y = (2.0f * texel.y - 1.0f) * map.scale;
  const float z = 2.0f * texel.z - 1.0f;
  const Vec3 mapped = t * (side * x) + b * y + n * z;
  const float mapped_length = length(mapped);
  if (!(mapped_length > 0.0f) || !std::isfinite(mapped_length)) return n;
  const Vec3 unit = mapped / mapped_length;
  return dot(unit, point.geometric_normal) > 0.0f ? unit : n;
}

}  // namespace rtpro
