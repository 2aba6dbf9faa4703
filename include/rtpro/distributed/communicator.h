#pragma once
// How the ranks of a distributed render talk: numbered processes that send each other tagged
// byte messages. Open MPI provides it (librtpro_mpi.so, loaded only when mpirun started rtpro);
// the scheduler (distributed_render.h) needs nothing more, so it is tested without MPI too.
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rtpro {

struct Message {
  int source = 0;
  int tag = 0;
  std::vector<std::byte> bytes;
};

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // Returns once the bytes may be reused; messages between two ranks arrive in order.
  virtual void send(int destination, int tag, std::span<const std::byte> bytes) = 0;
  // The next message for this rank if one has arrived, without waiting.
  virtual std::optional<Message> poll() = 0;
  // Ends every rank of the job now with `exit_code` (a fault on one rank must not leave the
  // others waiting for it).
  [[noreturn]] virtual void abort(int exit_code) = 0;
};

// Whether mpirun (Open MPI) started this process: only then does rtpro load MPI at all.
bool launched_by_mpirun();

// Loads librtpro_mpi.so from the executable's folder and joins the job (MPI_Init_thread, only
// the calling thread talks MPI). The communicator finalizes MPI when destroyed. Throws
// RuntimeError when the plugin or MPI cannot be loaded.
std::unique_ptr<Communicator> join_mpi_job();

// Leaves the job: destroys `job`, which finalizes MPI. MPI_Finalize waits for every rank, so one
// stopped, hung or unreachable after its last message would hold the others (and mpirun) for
// ever, with the image already written: after `rank_timeout` (zero: wait for ever) this rank says
// so on standard error and exits with kExitRuntimeFailure without finalizing, and mpirun then
// ends every rank of the job, the silent one too.
void leave_mpi_job(std::unique_ptr<Communicator> job, std::chrono::milliseconds rank_timeout);

}  // namespace rtpro
