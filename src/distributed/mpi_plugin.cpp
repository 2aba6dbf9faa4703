// librtpro_mpi.so: a Communicator on Open MPI's MPI_COMM_WORLD. Only the thread that joined the
// job calls MPI (MPI_THREAD_FUNNELED); the render workers never do.
#include "mpi_plugin_api.h"

#include <mpi.h>

#include <cstdlib>
#include <cstring>
#include <string>

namespace rtpro {
namespace {

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiCommunicator() override { MPI_Finalize(); }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void send(int destination, int tag, std::span<const std::byte> bytes) override {
    MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, destination, tag, MPI_COMM_WORLD);
  }

  std::optional<Message> poll() override {
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
  int rank_ = 0, size_ = 1;
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
