#include "interrupt.h"

#include <csignal>
#include <unistd.h>

namespace rtpro::cli {

namespace {

std::atomic<bool> g_requested{false};
struct sigaction g_previous_int, g_previous_term;

extern "C" void on_interrupt(int) {
  // Only async-signal-safe calls here: an atomic exchange, write(2) and _exit(2).
  if (g_requested.exchange(true)) {
    constexpr char kMessage[] = "\nrtpro: interrupted again, exiting now\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
    _exit(130);
  }
  constexpr char kMessage[] = "\nrtpro: interrupted, finishing the tiles in flight (interrupt again to quit now)\n";
  [[maybe_unused]] const auto n = write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_requested = false;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

const std::atomic<bool>& InterruptGuard::requested() { return g_requested; }

}  // namespace rtpro::cli
