#pragma once
// The messages the ranks of a job exchange: their tags (one list, so no two kinds share one), and
// waiting for the next.
#include "rtpro/distributed/communicator.h"

#include <chrono>
#include <optional>
#include <thread>
#include <utility>

namespace rtpro {

// kFinished: rank 0 has every rank's kDone of this image. A follower waits for it before it
// returns, so that nothing it sends for the next frame (its hello) can reach rank 0 while rank 0
// still waits for another follower's kDone of this one. kAlive: a heartbeat (rank_liveness.h).
// kLeave: rank 0 has written everything and finalizes MPI (leave_mpi_job).
enum Tag : int {
  kHello = 1,
  kVerdict = 2,
  kRequest = 3,
  kGrant = 4,
  kTile = 5,
  kDone = 6,
  kFinished = 7,
  kAlive = 8,
  kLeave = 9,
};

// The next message, however long it takes to come.
inline Message wait_for_message(Communicator& communicator) {
  constexpr auto kPollPause = std::chrono::microseconds(200);
  while (true) {
    if (std::optional<Message> message = communicator.poll()) return std::move(*message);
    std::this_thread::sleep_for(kPollPause);
  }
}

// The next message if one comes before `deadline`.
inline std::optional<Message> wait_for_message_until(Communicator& communicator,
                                                     std::chrono::steady_clock::time_point deadline) {
  constexpr auto kPollPause = std::chrono::microseconds(200);
  while (true) {
    if (std::optional<Message> message = communicator.poll()) return message;
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(kPollPause);
  }
}

}  // namespace rtpro
