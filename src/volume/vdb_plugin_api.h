#pragma once
// The table of librtpro_vdb.so, the plugin that holds rtpro's only calls into OpenVDB. Linked into
// the executable, OpenVDB costs every run 90 ms of symbol binding and 31 MB of resident pages
// (its 22 MB symbol string table among them) before main(); as a plugin it is loaded by the first
// scene that names a .vdb file. Plugin and executable come from one build; the version fields
// catch a stale plugin left beside a newer executable.
#include "rtpro/volume/vdb_file.h"

namespace rtpro {

// Raise whenever a call is added, removed or changes its signature.
inline constexpr int kVdbPluginAbiVersion = 2;
inline constexpr const char* kVdbPluginEntryPoint = "rtpro_vdb_plugin";
inline constexpr const char* kVdbPluginFileName = "librtpro_vdb.so";

struct VdbPluginApi {
  int abi_version;
  const char* rtpro_version;
  std::uint64_t (*estimate_bytes)(const VdbRequest&);
  VdbGrids (*read_grids)(const VdbRequest&);
  void (*write_file)(const std::filesystem::path&, std::span<const VdbGridSpec>, VdbCompression);
};

// The plugin's one exported symbol, named by kVdbPluginEntryPoint, is a `const VdbPluginApi* ()`
// (opened by core/plugin_file.h's open_plugin_table).

}  // namespace rtpro
