// vdb_file.h's calls in whatever links rtpro_volume: each loads librtpro_vdb.so (vdb_plugin_api.h)
// on first use and forwards to it.
#include "rtpro/volume/vdb_file.h"

#include "rtpro/core/error.h"
#include "rtpro/core/plugin_file.h"
#include "vdb_plugin_api.h"

#include <string>

namespace rtpro {

namespace {

const VdbPluginApi* load_plugin() {
  const std::filesystem::path file = plugin_beside_executable(kVdbPluginFileName, "OpenVDB files");
  return open_plugin_table<VdbPluginApi>(file, kVdbPluginEntryPoint, kVdbPluginAbiVersion, RTPRO_VERSION,
                                         "OpenVDB to read .vdb files");
}

// A failed load is not remembered: the next call tries again and reports the same error.
const VdbPluginApi& vdb_plugin() {
  static const VdbPluginApi* const api = load_plugin();
  return *api;
}

}  // namespace

std::uint64_t estimate_vdb_bytes(const VdbRequest& request) { return vdb_plugin().estimate_bytes(request); }

VdbGrids read_vdb_grids(const VdbRequest& request) { return vdb_plugin().read_grids(request); }

void write_vdb_file(const std::filesystem::path& file, std::span<const VdbGridSpec> grids, VdbCompression compression) {
  vdb_plugin().write_file(file, grids, compression);
}

}  // namespace rtpro
