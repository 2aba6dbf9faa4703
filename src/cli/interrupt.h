#pragma once
// Ctrl-C and SIGTERM during a render: the first one asks the renderer to stop after the tiles in
// flight (so the finished part can be saved); a second one exits at once with code 130.
#include <atomic>

namespace rtpro::cli {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // Set by the first signal; hand it to RenderOptions::cancel.
  static const std::atomic<bool>& requested();
};

}  // namespace rtpro::cli
