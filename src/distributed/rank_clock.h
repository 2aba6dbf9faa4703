#pragma once
// A rank's own figures while it renders: tiles and rays done, and thread-seconds spent rendering
// (from a tile handed to a worker to the tile finished) and waiting for work.
#include "rtpro/render/tiles.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>

namespace rtpro {

class RankClock {
 public:
  using Clock = std::chrono::steady_clock;

  // Times one wait for a tile, and starts the worker's busy time when it ends.
  class Wait {
   public:
    explicit Wait(RankClock& clock) : clock_(clock), start_(Clock::now()) {}
    ~Wait() {
      const Clock::time_point end = Clock::now();
      clock_.idle_ns_ += std::chrono::duration_cast<std::chrono::nanoseconds>(end - start_).count();
      busy_since() = end;
    }

   private:
    RankClock& clock_;
    Clock::time_point start_;
  };

  void tile_done(const TileResult& tile) {
    busy_ns_ += std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - busy_since()).count();
    const std::lock_guard lock(mutex_);
    ++tiles_;
    rays_ += tile.rays;
  }

  std::uint64_t tiles() const {
    const std::lock_guard lock(mutex_);
    return tiles_;
  }
  RayCounts rays() const {
    const std::lock_guard lock(mutex_);
    return rays_;
  }
  double busy_seconds() const { return double(busy_ns_.load()) * 1e-9; }
  double idle_seconds() const { return double(idle_ns_.load()) * 1e-9; }

 private:
  // Each worker thread renders one tile at a time, from the end of its wait to tile_done.
  static Clock::time_point& busy_since() {
    thread_local Clock::time_point since = Clock::now();
    return since;
  }

  std::atomic<std::int64_t> busy_ns_{0}, idle_ns_{0};
  mutable std::mutex mutex_;
  std::uint64_t tiles_ = 0;
  RayCounts rays_;
};

}  // namespace rtpro
