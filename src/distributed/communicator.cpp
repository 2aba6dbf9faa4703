#include "rtpro/distributed/communicator.h"

#include "job_messages.h"
#include "mpi_plugin_api.h"
#include "rtpro/core/error.h"
#include "rtpro/core/plugin_file.h"

#include <dlfcn.h>

#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <thread>

namespace rtpro {

bool launched_by_mpirun() {
  // Open MPI's launcher sets these in every process it starts (PMIx for Open MPI 4 and later).
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr;
}

std::unique_ptr<Communicator> join_mpi_job() {
  const std::filesystem::path file = plugin_beside_executable(kMpiPluginFileName, "MPI");
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

namespace {

// Rank 0 tells the others it has written everything; they wait for that (as for its verdict at a
// job's start: rank 0 may be writing or denoising a large image meanwhile), so that no rank's
// finalize deadline runs while rank 0 still works.
void agree_to_leave(Communicator& job) {
  if (job.rank() == 0) {
    for (int rank = 1; rank < job.size(); ++rank) job.send(rank, kLeave, {});
    return;
  }
  while (true) {
    const Message message = wait_for_message(job);
    if (message.tag == kLeave) return;
    if (message.tag != kAlive) throw RuntimeError("distributed render: rank 0 sent an unexpected message at the end");
  }
}

}  // namespace

void leave_mpi_job(std::unique_ptr<Communicator> job, std::chrono::milliseconds rank_timeout) {
  if (!job) return;
  agree_to_leave(*job);
  if (rank_timeout.count() <= 0) {
    job.reset();
    return;
  }
  const int rank = job->rank();
  std::mutex mutex;
  std::condition_variable finalized;
  bool done = false;
  // A thread of its own: the thread that joined the job is the one that must finalize it.
  std::thread watchdog([&] {
    std::unique_lock lock(mutex);
    if (finalized.wait_for(lock, rank_timeout, [&] { return done; })) return;
    std::fprintf(stderr,
                 "rtpro: error on rank %d: the end of the MPI job (MPI_Finalize) waited %.0f s (--rank-timeout) for "
                 "another rank: one is stopped, hung or unreachable, so the job ends\n",
                 rank, std::chrono::duration<double>(rank_timeout).count());
    std::fflush(stderr);
    std::_Exit(kExitRuntimeFailure);
  });
  job.reset();
  {
    const std::lock_guard lock(mutex);
    done = true;
  }
  finalized.notify_one();
  watchdog.join();
}

}  // namespace rtpro
