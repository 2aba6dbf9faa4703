#include "atomic_file_replacement.h"

#include "rtpro/core/error.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <random>
#include <sstream>
#include <system_error>
#include <unistd.h>

namespace rtpro {

namespace {

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

void require_writable_folder(const std::filesystem::path& folder) {
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    throw RuntimeError("cannot write into " + folder.string() + ": no such folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw RuntimeError("cannot write into " + folder.string() + ": " + std::strerror(errno));
}

std::filesystem::path temporary_name_beside(const std::filesystem::path& target) {
  std::random_device entropy;
  std::ostringstream name;
  name << '.' << target.stem().string() << ".tmp-" << ::getpid() << '-' << std::hex << entropy()
       << target.extension().string();
  return folder_of(target) / name.str();
}

void flush_to_disk(const std::filesystem::path& file) {
  const int descriptor = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) throw RuntimeError("cannot reopen " + file.string() + ": " + std::strerror(errno));
  const int result = ::fsync(descriptor);
  const int fsync_errno = errno;
  ::close(descriptor);
  if (result != 0) throw RuntimeError("cannot flush " + file.string() + ": " + std::strerror(fsync_errno));
}

}  // namespace

AtomicFileReplacement::AtomicFileReplacement(std::filesystem::path target) : target_(std::move(target)) {
  require_writable_folder(folder_of(target_));
  temporary_ = temporary_name_beside(target_);
}

AtomicFileReplacement::~AtomicFileReplacement() {
  if (committed_) return;
  std::error_code ignored;  // nothing useful to do if cleanup fails while another error unwinds
  std::filesystem::remove(temporary_, ignored);
}

void AtomicFileReplacement::commit() {
  flush_to_disk(temporary_);
  std::error_code error;
  std::filesystem::rename(temporary_, target_, error);
  if (error) throw RuntimeError("cannot replace " + target_.string() + ": " + error.message());
  committed_ = true;
}

}  // namespace rtpro
