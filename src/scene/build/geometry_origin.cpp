#include "geometry_origin.h"

#include "gltf_asset.h"

namespace rtpro {

InputError geometry_error(const GeometryOrigin& origin, const std::string& message) {
  if (!origin.gltf) return InputError(*origin.where, message);
  const bool in_the_gltf_itself =
      std::filesystem::path(origin.where->file).lexically_normal() == origin.gltf->lexically_normal();
  const std::string file = in_the_gltf_itself ? "" : origin.gltf->string() + ": ";
  return InputError(*origin.where, file + gltf_node_path(origin.gltf_node) + ": " + message);
}

}  // namespace rtpro
