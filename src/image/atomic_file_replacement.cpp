#include "rtpro/image/atomic_file_replacement.h"

#include "rtpro/core/error.h"
#include "rtpro/core/special_file_kind.h"
#include "rtpro/core/stale_temporaries.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace rtpro {

namespace {

constexpr std::string_view kTemporaryMarker = ".rtpro-tmp-";

std::filesystem::path folder_of(const std::filesystem::path& file) {
  return file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& why) {
  throw RuntimeError("cannot write " + file.string() + ": " + why);
}

[[noreturn]] void fail_errno(const std::filesystem::path& file, const char* step, int error) {
  fail(file, std::string(step) + ": " + std::strerror(error));
}

void write_all(int descriptor, std::string_view bytes, const std::filesystem::path& target) {
  while (!bytes.empty()) {
    const ssize_t written = ::write(descriptor, bytes.data(), bytes.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0) fail_errno(target, "write", errno);
    if (written == 0) fail(target, "write: no progress");
    bytes.remove_prefix(static_cast<std::size_t>(written));
  }
}

}  // namespace

std::string temporary_prefix(const std::filesystem::path& target) {
  return "." + target.filename().string() + std::string(kTemporaryMarker);
}

void check_replaceable(const std::filesystem::path& target) {
  if (target.empty() || !target.has_filename()) fail(target, "no file name");
  const std::filesystem::path folder = folder_of(target);
  struct stat folder_status {};
  if (::stat(folder.c_str(), &folder_status) != 0 || !S_ISDIR(folder_status.st_mode))
    fail(target, "folder '" + folder.string() + "' does not exist");
  if (::access(folder.c_str(), W_OK | X_OK) != 0) fail(target, "folder '" + folder.string() + "' is not writable");
  struct stat status {};
  if (::lstat(target.c_str(), &status) == 0 && !S_ISREG(status.st_mode)) {
    fail(target, std::string("it is ") + special_file_kind(status.st_mode) +
                     "; rtpro replaces only regular files (remove it or choose another name)");
  }
  // A full file system is known before anything is rendered; a nearly full one shows up as a
  // failed write later, with the old file kept. One without blocks at all (/proc, /sys) is not
  // full: creating the file there fails and says why.
  struct statvfs space {};
  if (::statvfs(folder.c_str(), &space) == 0 && space.f_blocks > 0 &&
      (::geteuid() == 0 ? space.f_bfree : space.f_bavail) == 0)
    fail(target, "the file system of folder '" + folder.string() + "' is full");
}

AtomicFileReplacement::AtomicFileReplacement(std::filesystem::path target) : target_(std::move(target)) {
  check_replaceable(target_);
  remove_stale_temporaries(folder_of(target_), temporary_prefix(target_));
  create_temporary();
}

// The temporary's name is predictable (PID and a counter), so another user of a shared folder
// could plant a file or symbolic link there: create_owned_temporary never opens or removes it.
void AtomicFileReplacement::create_temporary() {
  descriptor_ = create_owned_temporary(folder_of(target_), temporary_prefix(target_), temporary_);
  if (descriptor_ < 0) {
    const int error = errno;
    temporary_.clear();
    if (error == EEXIST) fail(target_, "create: the temporary names beside it are all taken by other files");
    fail_errno(target_, "create", error);
  }
  struct stat created {};
  if (::fstat(descriptor_, &created) != 0) fail_errno(target_, "create", errno);
  device_ = created.st_dev;
  inode_ = created.st_ino;
}

AtomicFileReplacement::~AtomicFileReplacement() {
  if (descriptor_ >= 0) ::close(descriptor_);
  if (committed_ || temporary_.empty()) return;
  // Only the file created: another put in its place meanwhile is not rtpro's to remove.
  struct stat now {};
  if (::lstat(temporary_.c_str(), &now) == 0 && now.st_dev == device_ && now.st_ino == inode_)
    ::unlink(temporary_.c_str());
}

void AtomicFileReplacement::commit() {
  // fsync is per file: the descriptor opened at creation flushes what a library wrote by name.
  if (::fsync(descriptor_) != 0) fail_errno(target_, "flush", errno);
  const int closed = ::close(descriptor_);
  descriptor_ = -1;
  if (closed != 0) fail_errno(target_, "close", errno);
  // The file renamed is the one created: not a link or file put in its place meanwhile.
  struct stat now {};
  if (::lstat(temporary_.c_str(), &now) != 0 || !S_ISREG(now.st_mode) || now.st_dev != device_ || now.st_ino != inode_)
    fail(target_, "its temporary file '" + temporary_.string() + "' was replaced by another file while it was written");
  // Checked again just before the rename: a symlink or device put there during the render is
  // refused, not replaced.
  check_replaceable(target_);
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) fail_errno(target_, "rename", errno);
  committed_ = true;
  // The rename itself reaches the disk only with the folder; a failure here leaves the complete
  // new file in place, so it is not worth failing the run for.
  const int folder = ::open(folder_of(target_).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder >= 0) {
    ::fsync(folder);
    ::close(folder);
  }
}

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes) {
  AtomicFileReplacement replacement(target);
  write_all(replacement.descriptor(), bytes, target);
  replacement.commit();
}

}  // namespace rtpro
