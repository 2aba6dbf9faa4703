#include "rtpro/render/pixel_sums.h"

namespace rtpro {

SumLayout::SumLayout(std::span<const Aov> aovs, ExtraSums extra) {
  const auto take = [&](int& offset, bool kept, int count) {
    if (!kept) return;
    offset = floats_;
    floats_ += count;
  };
  // Every layer is named here, so a new one does not compile until it says which sums it reads.
  bool halves = false, variance = false, albedo = false, normal = false, depth = false, object_id = false,
       motion = false;
  for (Aov aov : aovs) {
    switch (aov) {
      case Aov::kAlbedo: albedo = true; break;
      case Aov::kNormal: normal = true; break;
      case Aov::kDepth: depth = true; break;
      case Aov::kObjectId: object_id = true; break;
      case Aov::kHalves: halves = true; break;
      case Aov::kVariance: variance = true; break;
      case Aov::kSpp: break;  // the sample count is always kept
      case Aov::kMotion: motion = true; break;
    }
  }
  take(even_, halves || extra.even_half, 3);
  take(odd_, halves, 3);
  take(squared_, variance || extra.squares, 3);
  take(albedo_, albedo, 3);
  take(normal_, normal, 3);
  take(depth_, depth || motion, 2);  // the motion's mean reads the hit count
  take(object_id_, object_id, 1);
  take(motion_, motion, 4);
}

}  // namespace rtpro
