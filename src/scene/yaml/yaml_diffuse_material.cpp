#include "rtpro/scene/diffuse_material.h"

#include "yaml_reader.h"

namespace rtpro {

std::vector<std::string_view> material_keys(const DiffuseParams&) { return {}; }

void read_material_params(const MappingReader&, DiffuseParams&) {}

}  // namespace rtpro
