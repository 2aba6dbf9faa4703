#pragma once
// A follower's two queues between its talking thread and its workers: the tiles rank 0 granted,
// waiting for a worker, and the finished tiles, waiting to be sent.
#include "rank_clock.h"
#include "rtpro/render/renderer.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace rtpro {

// A follower's tiles: indices granted by rank 0, taken by its workers.
class GrantedTiles final : public TileSource {
 public:
  // `running_low` is called (by a worker) when a tile taken leaves fewer than the low-water mark.
  GrantedTiles(RankClock& clock, const std::atomic<bool>* cancel, std::function<void()> running_low)
      : clock_(clock), cancel_(cancel), running_low_(std::move(running_low)) {}
  std::optional<std::size_t> next() override {
    const RankClock::Wait wait(clock_);
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return !queue_.empty() || no_more_; });
    if (queue_.empty() || (cancel_ && cancel_->load())) return std::nullopt;
    const std::size_t index = queue_.front();
    queue_.pop_front();
    const bool low = queue_.size() < low_water_ && !no_more_;
    lock.unlock();
    if (low) running_low_();
    return index;
  }
  void set_low_water(std::size_t tiles) {
    const std::lock_guard lock(mutex_);
    low_water_ = tiles;
  }
  void add(const std::vector<std::uint64_t>& indices) {
    {
      const std::lock_guard lock(mutex_);
      queue_.insert(queue_.end(), indices.begin(), indices.end());
    }
    ready_.notify_all();
  }
  void finish() {
    {
      const std::lock_guard lock(mutex_);
      no_more_ = true;
    }
    ready_.notify_all();
  }
  // The job is ending: the queued tiles are left (rank 0's journal does not have them).
  void stop() {
    {
      const std::lock_guard lock(mutex_);
      queue_.clear();
      no_more_ = true;
    }
    ready_.notify_all();
  }
  std::size_t queued() {
    const std::lock_guard lock(mutex_);
    return queue_.size();
  }

 private:
  RankClock& clock_;
  const std::atomic<bool>* cancel_;
  std::function<void()> running_low_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::size_t> queue_;
  std::size_t low_water_ = 0;
  bool no_more_ = false;
};

// A follower's finished tiles, waiting for the main thread to send them.
class OutgoingTiles final : public TileSink {
 public:
  explicit OutgoingTiles(RankClock& clock) : clock_(clock) {}
  // Finished tiles wait for the talking thread's next wake-up: one per tile would cost a worker its
  // core each time.
  void put(TileResult&& tile) override {
    clock_.tile_done(tile);
    const std::lock_guard lock(mutex_);
    tiles_.push_back(std::move(tile));
  }
  // Waits until wake() or `wait` has passed, then takes the finished tiles.
  std::deque<TileResult> take(std::chrono::microseconds wait) {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, wait, [&] { return woken_; });
    woken_ = false;
    return std::exchange(tiles_, {});
  }
  void wake() {
    {
      const std::lock_guard lock(mutex_);
      woken_ = true;
    }
    changed_.notify_one();
  }

 private:
  RankClock& clock_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<TileResult> tiles_;
  bool woken_ = false;
};

}  // namespace rtpro
