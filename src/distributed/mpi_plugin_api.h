#pragma once
// The entry point of librtpro_mpi.so, the plugin that holds rtpro's only calls into Open MPI, so
// that the executable neither links nor loads MPI unless mpirun started it.
#include "rtpro/distributed/communicator.h"

namespace rtpro {

inline constexpr const char* kMpiPluginFileName = "librtpro_mpi.so";
inline constexpr const char* kMpiPluginEntryPoint = "rtpro_join_mpi_job";
inline constexpr int kMpiPluginAbiVersion = 1;

// Returns a new communicator, or nullptr with `error` set. `version` must be RTPRO_VERSION and
// `abi` kMpiPluginAbiVersion of the caller, so a stale plugin is refused.
using MpiPluginEntryPoint = Communicator* (*)(const char* version, int abi, std::string* error);

}  // namespace rtpro
