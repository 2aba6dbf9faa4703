#include "fuzz_workspace.h"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace rtpro::fuzz {

namespace {

// Owns the folder and removes it when static objects are destroyed. The removal must not be an
// atexit handler registered while the folder's path is being made: handlers and destructors run in
// reverse order of registration, so such a handler would run after the path's own destructor and
// read freed memory (valgrind showed it on every exit).
class Workspace {
 public:
  Workspace() {
    std::error_code error;
    const std::filesystem::path base =
        std::filesystem::is_directory("/dev/shm", error) && ::access("/dev/shm", W_OK) == 0
            ? std::filesystem::path("/dev/shm")
            : std::filesystem::temp_directory_path();
    std::string pattern = (base / "rtpro-fuzz-XXXXXX").string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a fuzz workspace in " + base.string());
    folder_ = pattern;
  }
  ~Workspace() {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  const std::filesystem::path& folder() const { return folder_; }

 private:
  std::filesystem::path folder_;
};

}  // namespace

const std::filesystem::path& workspace() {
  static const Workspace folder;
  return folder.folder();
}

std::filesystem::path write_workspace_file(std::string_view name, std::string_view bytes) {
  const std::filesystem::path file = workspace() / name;
  std::FILE* out = std::fopen(file.c_str(), "wb");
  if (!out) throw std::runtime_error("cannot write " + file.string());
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
  if (std::fclose(out) != 0 || !written) throw std::runtime_error("cannot write " + file.string());
  return file;
}

void remove_workspace_file(std::string_view name) {
  std::error_code ignored;
  std::filesystem::remove(workspace() / name, ignored);
}

}  // namespace rtpro::fuzz
