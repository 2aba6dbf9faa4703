#include "fuzz_workspace.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace rtpro::fuzz {

namespace {

std::filesystem::path make_workspace() {
  std::error_code error;
  const std::filesystem::path base =
      std::filesystem::is_directory("/dev/shm", error) && ::access("/dev/shm", W_OK) == 0
          ? std::filesystem::path("/dev/shm")
          : std::filesystem::temp_directory_path();
  std::string pattern = (base / "rtpro-fuzz-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a fuzz workspace in " + base.string());
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(workspace(), ignored);
  });
  return pattern;
}

}  // namespace

const std::filesystem::path& workspace() {
  static const std::filesystem::path folder = make_workspace();
  return folder;
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
