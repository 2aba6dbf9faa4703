// Fuzz target: an OBJ file and the MTL file it may name, through the public mesh loader.
//
// Input: the OBJ text, optionally followed by a line "#---mtl---" and the text of model.mtl (the
// OBJ reaches it with "mtllib model.mtl"). Without the marker there is no model.mtl.
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/scene/mesh_loader.h"

#include <cstdint>
#include <string_view>

namespace {
constexpr std::string_view kMtlMarker = "\n#---mtl---\n";
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const std::size_t marker = input.find(kMtlMarker);
  if (marker == std::string_view::npos) {
    rtpro::fuzz::remove_workspace_file("model.mtl");
  } else {
    rtpro::fuzz::write_workspace_file("model.mtl", input.substr(marker + kMtlMarker.size()));
  }
  const auto obj = rtpro::fuzz::write_workspace_file("model.obj", input.substr(0, marker));
  try {
    rtpro::load_mesh_file(obj);
  } catch (const rtpro::InputError&) {
  }
  return 0;
}
