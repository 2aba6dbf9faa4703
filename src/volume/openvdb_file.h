#pragma once
// The calls of vdb_file.h as OpenVDB answers them (openvdb_file.cpp). Only librtpro_vdb.so holds
// them; the executable reaches them through that plugin's table (vdb_plugin_api.h).
#include "rtpro/volume/vdb_file.h"

namespace rtpro {

std::uint64_t openvdb_estimate_bytes(const VdbRequest& request);
VdbGrids openvdb_read_grids(const VdbRequest& request);
void openvdb_write_file(const std::filesystem::path& file, std::span<const VdbGridSpec> grids,
                        VdbCompression compression);

}  // namespace rtpro
