#include "rtpro/core/temporary_folder.h"

#include "rtpro/core/error.h"
#include "rtpro/core/stale_temporaries.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

namespace rtpro {

TemporaryFolder::TemporaryFolder(std::string_view prefix, std::string_view purpose) {
  const char* folder = std::getenv("TMPDIR");
  const std::filesystem::path base = folder && *folder ? folder : "/tmp";
  remove_stale_temporaries(base, prefix);
  for (int attempt = 0; attempt < 64; ++attempt) {
    const std::filesystem::path candidate = base / owned_temporary_name(prefix);
    if (::mkdir(candidate.c_str(), 0700) == 0) {
      path_ = candidate;
      return;
    }
    if (errno != EEXIST) break;
  }
  throw RuntimeError("cannot create a folder for " + std::string(purpose) + " under " + base.string() + ": " +
                     std::strerror(errno));
}

TemporaryFolder::TemporaryFolder(TemporaryFolder&& other) noexcept : path_(std::exchange(other.path_, {})) {}

TemporaryFolder::~TemporaryFolder() {
  if (path_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace rtpro
