// Fuzz target: an OpenVDB file through the public calls a scene's volume entry makes: the memory
// estimate from its metadata, then the grids themselves (librtpro_vdb.so, beside the target).
#include "fuzz_workspace.h"
#include "rtpro/core/error.h"
#include "rtpro/volume/vdb_file.h"

#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  rtpro::VdbRequest request;
  request.file = rtpro::fuzz::write_workspace_file("grid.vdb", {reinterpret_cast<const char*>(data), size});
  request.where = rtpro::SourceLocation{"scene.yaml", 1, 1};
  request.max_bytes = 256ull << 20;  // the scene target's --max-memory 256
  try {
    rtpro::estimate_vdb_bytes(request);
    rtpro::read_vdb_grids(request);
  } catch (const rtpro::InputError&) {
  }
  return 0;
}
