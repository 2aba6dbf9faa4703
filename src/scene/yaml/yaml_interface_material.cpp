#include "rtpro/scene/interface_material.h"

#include "yaml_reader.h"

namespace rtpro {

std::vector<std::string_view> material_keys(const InterfaceParams&) { return {}; }

void read_material_params(const MappingReader&, InterfaceParams&) {}

}  // namespace rtpro
