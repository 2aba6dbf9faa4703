#include "rtpro/core/stale_temporaries.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>

namespace rtpro {

namespace {

bool process_is_gone(long pid) { return pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

}  // namespace

std::string owned_temporary_name(std::string_view prefix) {
  static std::atomic<unsigned> sequence{0};
  return std::string(prefix) + std::to_string(::getpid()) + "-" + std::to_string(sequence.fetch_add(1));
}

int create_owned_temporary(const std::filesystem::path& folder, std::string_view prefix,
                           std::filesystem::path& created) {
  constexpr int kNames = 64;
  for (int attempt = 0; attempt < kNames; ++attempt) {
    const std::filesystem::path candidate = folder / owned_temporary_name(prefix);
    const int descriptor = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (descriptor >= 0) {
      created = candidate;
      return descriptor;
    }
    if (errno != EEXIST) return -1;
  }
  return -1;  // errno is EEXIST: every name tried was taken
}

void remove_stale_temporaries(const std::filesystem::path& folder, std::string_view prefix) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const char* digits = name.c_str() + prefix.size();
    long pid = 0;
    const auto [after, parsed] = std::from_chars(digits, name.c_str() + name.size(), pid);
    if (parsed != std::errc() || *after != '-') continue;
    std::error_code ignored;
    if (!process_is_gone(pid) || it->is_symlink(ignored)) continue;
    // A folder (the decoded textures of a killed render) goes with its contents; remove_all does
    // not follow symbolic links inside it.
    if (it->is_directory(ignored)) std::filesystem::remove_all(it->path(), ignored);
    else std::filesystem::remove(it->path(), ignored);
  }
}

}  // namespace rtpro
