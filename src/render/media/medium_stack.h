#pragma once
// The media a path is inside, innermost last (Cycles' volume stack, without priorities): crossing
// a surface that bounds a medium (Material::interior) from its front enters that medium, crossing
// it from the back leaves it, wherever it is in the stack, so liquid in a glass works whether its
// surface lies inside the glass's inner wall or a little beyond it. Outside every entry is the
// world's medium. Four levels deep; a fifth enters in place of the innermost.
#include "rtpro/scene/medium_kinds.h"

#include <array>
#include <cstdint>

namespace rtpro {

struct MediumStack {
  static constexpr std::uint8_t kCapacity = 4;
  std::array<MediumIndex, kCapacity> media{};
  std::uint8_t depth = 0;

  // The medium the path is in (kNoMedium: vacuum); `world` outside every entry.
  MediumIndex current(MediumIndex world) const { return depth > 0 ? media[depth - 1] : world; }

  void enter(MediumIndex medium) {
    if (depth == kCapacity) --depth;
    media[depth++] = medium;
  }
  // A path leaving what it never entered (its camera was inside) stays where it is.
  void leave(MediumIndex medium) {
    for (int i = depth - 1; i >= 0; --i)
      if (media[i] == medium) {
        for (int j = i; j + 1 < depth; ++j) media[j] = media[j + 1];
        --depth;
        return;
      }
  }
  // Crossing a surface whose inside is `interior`, entering it when `front_face`.
  void cross(MediumIndex interior, bool front_face) {
    if (front_face) enter(interior);
    else leave(interior);
  }
};

}  // namespace rtpro
