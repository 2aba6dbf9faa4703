#pragma once
// Whether the other ranks of a render are still there. A rank that dies ends the job through
// mpirun, but a stopped (SIGSTOP), hung or unreachable one would hold every other rank for ever:
// each talking thread says "alive" every kHeartbeat, and a rank not heard from for longer than the
// rank timeout (--rank-timeout) ends the job as a dead one does.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

namespace rtpro {

class RankLiveness {
 public:
  using Clock = std::chrono::steady_clock;
  // Well under any timeout allowed (1 s and up), and a few small messages a second at most.
  static constexpr auto kHeartbeat = std::chrono::milliseconds(250);

  // `timeout` zero: never time out. Every rank counts as heard from now.
  RankLiveness(int ranks, std::chrono::milliseconds timeout)
      : timeout_(timeout), last_heard_(static_cast<std::size_t>(ranks), Clock::now()), last_beat_(Clock::now()) {}

  void heard(int rank) { last_heard_[static_cast<std::size_t>(rank)] = Clock::now(); }
  bool silent_too_long(int rank) const {
    return timeout_.count() > 0 && Clock::now() - last_heard_[static_cast<std::size_t>(rank)] > timeout_;
  }
  // True once every kHeartbeat: time to tell the others this rank is alive.
  bool heartbeat_due() {
    const Clock::time_point now = Clock::now();
    if (now - last_beat_ < kHeartbeat) return false;
    last_beat_ = now;
    return true;
  }
  // What ends the job when `rank` is silent_too_long.
  std::string silence(int rank) const {
    const double seconds =
        std::chrono::duration<double>(Clock::now() - last_heard_[static_cast<std::size_t>(rank)]).count();
    char text[64];
    std::snprintf(text, sizeof text, "%.1f s (--rank-timeout %g)", seconds,
                  std::chrono::duration<double>(timeout_).count());
    return "distributed render: rank " + std::to_string(rank) + " sent nothing for " + text +
           ": it is stopped, hung or unreachable, so the job ends; the journal keeps every tile that reached "
           "rank 0, and --resume continues";
  }

 private:
  std::chrono::milliseconds timeout_;
  std::vector<Clock::time_point> last_heard_;
  Clock::time_point last_beat_;
};

}  // namespace rtpro
