#include "progress.h"

#include "rtpro/core/error.h"

#include <cmath>
#include <cstdio>

namespace rtpro::cli {

ProgressMode parse_progress_mode(const std::string& text) {
  if (text == "never") return ProgressMode::kNever;
  if (text == "auto") return ProgressMode::kAuto;
  if (text == "always") return ProgressMode::kAlways;
  if (text == "json") return ProgressMode::kJson;
  throw InputError("--progress '" + text + "': expected never, auto, always or json");
}

std::string json_progress_line(std::size_t done, std::size_t total, double elapsed, bool final, long frame) {
  const double fraction = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  char text[256];
  if (final || done == 0) {
    std::snprintf(text, sizeof text,
                  "{\"tiles_done\":%zu,\"tiles_total\":%zu,\"fraction\":%.6f,\"elapsed_seconds\":%.3f,"
                  "\"eta_seconds\":%s,\"final\":%s}",
                  done, total, fraction, elapsed, final ? "0" : "null", final ? "true" : "false");
  } else {
    std::snprintf(text, sizeof text,
                  "{\"tiles_done\":%zu,\"tiles_total\":%zu,\"fraction\":%.6f,\"elapsed_seconds\":%.3f,"
                  "\"eta_seconds\":%.3f,\"final\":false}",
                  done, total, fraction, elapsed, elapsed * (1.0 - fraction) / fraction);
  }
  return frame < 0 ? std::string(text) : "{\"frame\":" + std::to_string(frame) + "," + std::string(text + 1);
}

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--";
  char text[32];
  const long total = std::lround(seconds);
  if (seconds < 60) std::snprintf(text, sizeof text, "%.1fs", seconds);
  else if (total < 3600) std::snprintf(text, sizeof text, "%ldm%02lds", total / 60, total % 60);
  else std::snprintf(text, sizeof text, "%ldh%02ldm", total / 3600, (total % 3600) / 60);
  return text;
}

ProgressReporter::ProgressReporter(ProgressMode mode, bool stderr_is_terminal, long frame)
    : enabled_(mode != ProgressMode::kNever), json_(mode == ProgressMode::kJson), frame_(frame),
      bar_(!json_ && (mode == ProgressMode::kAlways || stderr_is_terminal)), start_(std::chrono::steady_clock::now()),
      interval_(bar_ ? std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::milliseconds(250))
                : json_ ? std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::seconds(1))
                        : std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::seconds(5))) {}

void ProgressReporter::tile_done(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  const std::int64_t now = (std::chrono::steady_clock::now() - start_).count();
  std::int64_t due = next_update_ns_.load(std::memory_order_relaxed);
  if (now < due) return;
  // Only the thread that moves the deadline forward draws; the others go back to work.
  if (!next_update_ns_.compare_exchange_strong(due, now + interval_.count())) return;
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (lock) draw(done, total, false);
}

void ProgressReporter::finish(std::size_t done, std::size_t total) {
  if (!enabled_) return;
  std::lock_guard lock(mutex_);
  draw(done, total, true);
}

void ProgressReporter::draw(std::size_t done, std::size_t total, bool final) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = total ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : NAN;
  if (json_) {
    std::fprintf(stderr, "%s\n", json_progress_line(done, total, elapsed, final, frame_).c_str());
  } else if (bar_) {
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::string bar(filled, '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r[%s] %5.1f%%  elapsed %s  eta %s   ", bar.c_str(), 100.0 * fraction,
                 format_duration(elapsed).c_str(), final ? "0.0s" : format_duration(eta).c_str());
    if (final) std::fputc('\n', stderr);
  } else {
    std::fprintf(stderr, "rtpro: rendering %5.1f%% (%zu/%zu tiles), elapsed %s, eta %s\n", 100.0 * fraction, done,
                 total, format_duration(elapsed).c_str(), final ? "0.0s" : format_duration(eta).c_str());
  }
  std::fflush(stderr);
}

}  // namespace rtpro::cli
