// The entry point of librtpro_vdb.so: the table of openvdb_file.cpp's calls. Everything else in
// the plugin is hidden (--exclude-libs), so its copies of rtpro's code never interpose on the
// executable's.
#include "openvdb_file.h"
#include "vdb_plugin_api.h"

extern "C" __attribute__((visibility("default"))) const rtpro::VdbPluginApi* rtpro_vdb_plugin() {
  static const rtpro::VdbPluginApi api{rtpro::kVdbPluginAbiVersion, RTPRO_VERSION, &rtpro::openvdb_estimate_bytes,
                                       &rtpro::openvdb_read_grids, &rtpro::openvdb_write_file};
  return &api;
}
