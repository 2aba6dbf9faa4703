#include "tbb_workers.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace rtpro::cli {

void start_tbb_workers(int threads) {
  using Clock = std::chrono::steady_clock;
  std::atomic<int> arrived{0};
  const auto give_up = Clock::now() + std::chrono::milliseconds(50);
  tbb::parallel_for(
      0, threads,
      [&](int) {
        ++arrived;
        while (arrived.load() < threads && Clock::now() < give_up) std::this_thread::yield();
      },
      tbb::static_partitioner());
}

}  // namespace rtpro::cli
