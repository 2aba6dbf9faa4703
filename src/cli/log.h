#pragma once
// Messages on stderr at three levels (-q quiet, default, -v verbose). Repeated warnings are shown
// once, and summarised with their count at the end, so a mesh with 10,000 bad faces prints one line.
#include <cstddef>
#include <map>
#include <mutex>
#include <string>

namespace rtpro::cli {

enum class LogLevel { kQuiet = 0, kNormal = 1, kVerbose = 2 };

class Log {
 public:
  explicit Log(LogLevel level = LogLevel::kNormal) : level_(level) {}

  LogLevel level() const { return level_; }
  void info(const std::string& message);     // shown unless quiet
  void verbose(const std::string& message);  // shown with -v
  // Shown unless quiet, once per distinct message; later repeats only counted.
  void warning(const std::string& message);
  // "N more times" lines for warnings that repeated.
  void summarise_repeats();

 private:
  LogLevel level_;
  std::mutex mutex_;
  std::map<std::string, std::size_t> warnings_;
};

}  // namespace rtpro::cli
