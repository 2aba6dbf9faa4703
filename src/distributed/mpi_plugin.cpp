// librtpro_mpi.so: a Communicator on Open MPI's MPI_COMM_WORLD. Only the thread that joined the
// job calls MPI (MPI_THREAD_FUNNELED); the render workers never do.
#include "mpi_plugin_api.h"

#include <mpi.h>

#include <cstdlib>
#include <cstring>
#include <iterator>
#include <list>
#include <string>
#include <vector>

namespace rtpro {
namespace {

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiCommunicator() override {
    for (PendingSend& send : pending_) MPI_Wait(&send.request, MPI_STATUS_IGNORE);
    MPI_Finalize();
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  // A copy of the bytes goes out with MPI_Isend. A blocking MPI_Send of a tile larger than the
  // eager limit (4 KB on shared memory) waits for rank 0 to post the receive, spinning in
  // opal_progress meanwhile: rank 0 looks for messages every few milliseconds, so the follower's
  // talking thread burned ~8% of a core that its worker needed.
  void send(int destination, int tag, std::span<const std::byte> bytes) override {
    complete_sends();
    PendingSend& send = pending_.emplace_back();
    send.bytes.assign(bytes.begin(), bytes.end());
    MPI_Isend(send.bytes.data(), static_cast<int>(send.bytes.size()), MPI_BYTE, destination, tag, MPI_COMM_WORLD,
              &send.request);
  }

  std::optional<Message> poll() override {
    complete_sends();
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) return std::nullopt;
    int count = 0;
    MPI_Get_count(&status, MPI_BYTE, &count);
    Message message;
    message.source = status.MPI_SOURCE;
    message.tag = status.MPI_TAG;
    message.bytes.resize(static_cast<std::size_t>(count));
    MPI_Recv(message.bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    return message;
  }

  [[noreturn]] void abort(int exit_code) override {
    MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::_Exit(exit_code);
  }

 private:
  struct PendingSend {
    std::vector<std::byte> bytes;
    MPI_Request request = MPI_REQUEST_NULL;
  };

  void complete_sends() {
    for (auto send = pending_.begin(); send != pending_.end();) {
      int done = 0;
      MPI_Test(&send->request, &done, MPI_STATUS_IGNORE);
      send = done ? pending_.erase(send) : std::next(send);
    }
  }

  int rank_ = 0, size_ = 1;
  std::list<PendingSend> pending_;  // a list: the buffers must not move while MPI holds them
};

}  // namespace
}  // namespace rtpro

extern "C" __attribute__((visibility("default"))) rtpro::Communicator* rtpro_join_mpi_job(const char* version, int abi,
                                                                                          std::string* error) {
  if (abi != rtpro::kMpiPluginAbiVersion || std::strcmp(version, RTPRO_VERSION) != 0) {
    *error = std::string("librtpro_mpi.so is not the MPI plugin of this rtpro build (") + RTPRO_VERSION + ")";
    return nullptr;
  }
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    *error = "MPI_Init_thread failed";
    return nullptr;
  }
  if (provided < MPI_THREAD_FUNNELED) {
    *error = "this MPI library does not allow threads (MPI_THREAD_FUNNELED)";
    MPI_Finalize();
    return nullptr;
  }
  // Errors come back as codes and are checked where they matter; a dead peer ends the job through
  // mpirun, not through an error handler here.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  return new rtpro::MpiCommunicator();
}
