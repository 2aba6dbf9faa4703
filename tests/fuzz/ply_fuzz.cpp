// Fuzz target: a PLY file (ASCII or binary) through the public mesh loader.
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/scene/mesh_loader.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto ply = rtpro::fuzz::write_workspace_file("model.ply", {reinterpret_cast<const char*>(data), size});
  try {
    rtpro::load_mesh_file(ply);
  } catch (const rtpro::InputError&) {
  }
  return 0;
}
