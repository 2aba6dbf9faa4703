#pragma once
// Runs the real rtpro binary (or any program) and measures what the answer cost: wall time and
// the child's peak resident memory. A run that outlives `kill_after` seconds is killed, so a hang
// (a FIFO with no writer, say) fails the test instead of stalling the suite.
#include <string>
#include <vector>

namespace rtpro::test {

struct CappedRun {
  int exit_code = -1;        // 128 + signal when killed by one
  bool killed = false;       // by the kill_after limit
  double seconds = 0.0;      // wall time
  double cpu_seconds = 0.0;  // user + system time of the child: what it did, whatever else ran
  double peak_rss_mb = 0.0;
  std::string output;  // stdout and stderr together
};

// `argv[0]` is the program's path. `shell_prefix`, when given, runs the command through
// /bin/sh -c "PREFIX exec PROGRAM ARGS" (e.g. "trap '' XFSZ; ulimit -f 64;").
CappedRun run_capped(const std::vector<std::string>& argv, double kill_after = 30.0,
                     const std::string& shell_prefix = "");

// The cost of answering a trivial scene: what rtpro's start-up (libraries, colour config) costs
// before it reads anything. Measured once per test binary, the cheapest of three runs.
const CappedRun& startup_cost();

}  // namespace rtpro::test
