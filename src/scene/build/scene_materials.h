#pragma once
// The render scene's materials and the media they bound, added as the scene builder meets them:
// the scene file's own, a mesh file's (MTL) and a glTF file's, and each volume's boundary.
#include "rtpro/scene/render_scene.h"
#include "rtpro/scene/description.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace rtpro {

class SceneMaterials {
 public:
  explicit SceneMaterials(RenderScene& scene) : scene_(scene) {}

  // The material's index in scene.materials. Its images are registered as they are met: the
  // colour's, the model's own, the emission's.
  std::uint32_t add(const MaterialDesc& m, const std::string& name);
  MediumIndex add_medium(const Medium& medium);
  // The material of volume `v`'s boundary (scene.volumes[v]): an interface into its grid medium,
  // as Blender's Volume object has.
  std::uint32_t add_volume_boundary(std::size_t v);

 private:
  std::optional<MediumIndex> interior_medium(const MaterialDesc& m, const Material& material);

  RenderScene& scene_;
};

}  // namespace rtpro
