#include "capped_run.h"

#include "test_paths.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>

namespace rtpro::test {

namespace {

std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

}  // namespace

CappedRun run_capped(const std::vector<std::string>& argv, double kill_after, const std::string& shell_prefix) {
  std::vector<std::string> command = argv;
  if (!shell_prefix.empty()) {
    std::string line = shell_prefix + " exec";
    for (const std::string& arg : argv) line += " " + shell_quote(arg);
    command = {"/bin/sh", "-c", line};
  }
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) return {};
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::dup2(pipe_fds[1], STDERR_FILENO);
    const int null_input = ::open("/dev/null", O_RDONLY);
    ::dup2(null_input, STDIN_FILENO);
    std::vector<char*> args;
    for (std::string& arg : command) args.push_back(arg.data());
    args.push_back(nullptr);
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  ::close(pipe_fds[1]);
  CappedRun run;
  char buffer[4096];
  for (bool open = true; open;) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > kill_after && !run.killed) {
      ::kill(child, SIGKILL);
      run.killed = true;
    }
    pollfd descriptor{pipe_fds[0], POLLIN, 0};
    if (::poll(&descriptor, 1, 50) > 0) {
      const ssize_t got = ::read(pipe_fds[0], buffer, sizeof buffer);
      if (got <= 0) open = false;
      else run.output.append(buffer, static_cast<std::size_t>(got));
    }
  }
  ::close(pipe_fds[0]);
  int status = 0;
  rusage usage{};
  ::wait4(child, &status, 0, &usage);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;
  const auto seconds_of = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  run.cpu_seconds = seconds_of(usage.ru_utime) + seconds_of(usage.ru_stime);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return run;
}

const CappedRun& startup_cost() {
  static const CappedRun cheapest = [] {
    const auto scene = write_file("startup.yaml",
                                  "rtpro: 1\ncamera: {position: [0, 0, -5], look_at: [0, 0, 0], resolution: [4, 4]}\n");
    CappedRun best;
    best.seconds = 1e9;
    for (int i = 0; i < 3; ++i) {
      const CappedRun run = run_capped({rtpro_executable().string(), "info", scene.string()});
      if (run.seconds < best.seconds) best = run;
    }
    return best;
  }();
  return cheapest;
}

}  // namespace rtpro::test
