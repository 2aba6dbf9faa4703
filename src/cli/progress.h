#pragma once
// Render progress on stderr: a redrawn bar with percent, elapsed time and ETA on a terminal
// (a few updates a second), plain periodic lines otherwise. Called from worker threads after each
// tile; the cost per call is one atomic load unless an update is due.
#include "rtpro/render/render_observer.h"

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace rtpro::cli {

// kJson: one JSON object per line for render managers (json_progress_line), once a second and
// at the end.
enum class ProgressMode { kNever, kAuto, kAlways, kJson };

ProgressMode parse_progress_mode(const std::string& text);  // never | auto | always | json

// {"tiles_done":3,"tiles_total":12,"fraction":0.25,"elapsed_seconds":1.5,"eta_seconds":4.5,
// "final":false}; eta_seconds is null before the first tile. A frame of a sequence (frame >= 0)
// comes first: {"frame":12,"tiles_done":...}.
std::string json_progress_line(std::size_t done, std::size_t total, double elapsed, bool final, long frame = -1);

class ProgressReporter final : public RenderObserver {
 public:
  // kAuto draws a bar on a terminal and prints lines otherwise; kAlways forces the bar.
  ProgressReporter(ProgressMode mode, bool stderr_is_terminal, long frame = -1);

  void tile_done(std::size_t done, std::size_t total) override;
  void finish(std::size_t done, std::size_t total);  // final state, ends the bar's line

 private:
  void draw(std::size_t done, std::size_t total, bool final);

  bool enabled_;
  bool json_;
  long frame_;
  bool bar_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::duration interval_;
  std::atomic<std::int64_t> next_update_ns_{0};
  std::mutex mutex_;
};

// "1m05s" style durations for humans.
std::string format_duration(double seconds);

}  // namespace rtpro::cli
