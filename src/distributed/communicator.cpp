#include "rtpro/distributed/communicator.h"

#include "mpi_plugin_api.h"
#include "rtpro/core/error.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>

namespace rtpro {

bool launched_by_mpirun() {
  // Open MPI's launcher sets these in every process it starts (PMIx for Open MPI 4 and later).
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr;
}

std::unique_ptr<Communicator> join_mpi_job() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw RuntimeError("cannot load MPI: cannot find rtpro's own folder (/proc/self/exe: " + error.message() + ")");
  const std::filesystem::path file = executable.parent_path() / kMpiPluginFileName;
  // Global: Open MPI loads its own components with dlopen and needs its symbols visible to them.
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!handle)
    throw RuntimeError(std::string("cannot load MPI: ") + dlerror() + "; rtpro started by mpirun needs " +
                       kMpiPluginFileName + " from its own build beside the executable, and Open MPI");
  const auto entry = reinterpret_cast<MpiPluginEntryPoint>(dlsym(handle, kMpiPluginEntryPoint));
  if (!entry) throw RuntimeError("cannot load MPI: " + file.string() + " has no entry point; rebuild rtpro");
  std::string message;
  Communicator* communicator = entry(RTPRO_VERSION, kMpiPluginAbiVersion, &message);
  if (!communicator) throw RuntimeError("cannot join the MPI job: " + message);
  return std::unique_ptr<Communicator>(communicator);
}

}  // namespace rtpro
