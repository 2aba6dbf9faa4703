#include "texture.h"

#include "rtpro/core/math_constants.h"
#include "rtpro/core/overloaded.h"

#include <algorithm>
#include <cmath>

namespace rtpro {

namespace {

// Parity of the square (or cube) that `position` falls in; floor keeps squares the same size on
// both sides of zero.
int checker_parity(const CheckerTexture& checker, const Vec3& position) {
  const auto cell = [&](float coordinate) {
    return static_cast<long long>(std::floor(static_cast<double>(coordinate) * checker.inv_size));
  };
  long long sum = 0;
  switch (checker.axes) {
    case CheckerAxes::kXZ: sum = cell(position.x) + cell(position.z); break;
    case CheckerAxes::kXY: sum = cell(position.x) + cell(position.y); break;
    case CheckerAxes::kYZ: sum = cell(position.y) + cell(position.z); break;
    case CheckerAxes::kXYZ: sum = cell(position.x) + cell(position.y) + cell(position.z); break;
  }
  return static_cast<int>(sum & 1);
}

}  // namespace

namespace {

// Every kind of colour texture. Out of line: evaluate's test for a constant colour then needs no
// stack frame.
[[gnu::noinline]] Color evaluate_any_kind(const ColorTexture& texture, const SurfacePoint& point,
                                          const TextureLookup* images) {
  return std::visit(
      Overloaded{[](const Color& color) { return color; },
                 [&](const CheckerTexture& checker) {
                   return checker_parity(checker, point.position) == 0 ? checker.even : checker.odd;
                 },
                 [&](const ImageTexture& image) { return evaluate(image, point.tex_u, point.tex_v, images); }},
      texture);
}

}  // namespace

Color evaluate(const ColorTexture& texture, const SurfacePoint& point, const TextureLookup* images) {
  // A constant colour, what most materials have, before the dispatch.
  if (const Color* color = std::get_if<Color>(&texture)) return *color;
  return evaluate_any_kind(texture, point, images);
}

Color evaluate(const ImageTexture& texture, float u, float v, const TextureLookup* images) {
  // Texture coordinates have v up; the lookup's t runs down the image.
  return texture.tint * images->lookup(texture.image, u, 1.0f - v, texture.sampling);
}

Color emitted_radiance(const Emission& emission, float u, float v, const TextureLookup* images) {
  return emission.texture ? emission.radiance * evaluate(*emission.texture, u, v, images) : emission.radiance;
}

}  // namespace rtpro
