#pragma once
// What moves during the camera's shutter in a scene file (scene/motion.h): a keyframed value (or
// one that reads $frame) read again at the shutter's time steps, each step the value the scene
// would have on that (fractional) frame.
#include "rtpro/scene/motion.h"
#include "yaml_document.h"

#include <vector>

namespace rtpro {

class YamlMotion {
 public:
  YamlMotion() = default;  // nothing moves
  YamlMotion(const YamlDocument& document, const Shutter& shutter) : document_(&document), shutter_(shutter) {}

  // The steps of the transform `read(node)` gives, read at each step's frame: empty when it does
  // not change during the shutter. As many steps as keep a rotation on its arc
  // (sample_transform_motion).
  template <typename Read>
  std::vector<Affine> transform_steps(const YamlNode& node, Read&& read) const {
    if (!document_ || !shutter_.is_open()) return {};
    return sample_transform_motion(shutter_, document_->frame(),
                                   [&](double frame) { return read(*document_->at_frame(node, frame)); });
  }

  // The same for a position (a sphere's centre).
  template <typename Read>
  std::vector<Vec3> position_steps(const YamlNode& node, Read&& read) const {
    std::vector<Vec3> positions;
    for (const Affine& step : transform_steps(node, [&](const YamlNode& at) { return Affine::translate(read(at)); }))
      positions.push_back({step.m[0][3], step.m[1][3], step.m[2][3]});
    return positions;
  }

 private:
  const YamlDocument* document_ = nullptr;
  Shutter shutter_;
};

}  // namespace rtpro
