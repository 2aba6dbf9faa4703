#pragma once
// A private folder under $TMPDIR (or /tmp) for files only this process writes and reads back:
// "<prefix>PID-N", created 0700 by mkdir, so nothing another user planted can be inside it, and a
// name already taken is skipped, not reused or removed. The folders killed processes left under the
// same prefix are removed first (stale_temporaries.h); the folder and its contents go with the
// object.
#include <filesystem>
#include <string_view>

namespace rtpro {

class TemporaryFolder {
 public:
  // Throws RuntimeError naming `purpose` ("decoded textures") when no folder can be created.
  TemporaryFolder(std::string_view prefix, std::string_view purpose);
  ~TemporaryFolder();
  TemporaryFolder(TemporaryFolder&& other) noexcept;
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(TemporaryFolder&&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;  // empty once moved from
};

}  // namespace rtpro
