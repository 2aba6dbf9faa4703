#include "rtpro/job/journal_owner.h"

#include "rtpro/core/error.h"
#include "rtpro/job/tile_journal.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rtpro {

namespace {

// Whether `descriptor` is still the file at `path`: an owner that finished deletes its lock file,
// and a render that opened that file just before then locked a file no other render will see.
bool is_file_at(int descriptor, const std::filesystem::path& path) {
  struct stat opened {
  }, there{};
  return ::fstat(descriptor, &opened) == 0 && ::lstat(path.c_str(), &there) == 0 && S_ISREG(there.st_mode) &&
         opened.st_dev == there.st_dev && opened.st_ino == there.st_ino;
}

}  // namespace

std::filesystem::path journal_lock_path(const std::filesystem::path& journal) {
  std::filesystem::path lock = journal;
  lock += ".lock";
  return lock;
}

JournalOwner::JournalOwner(std::filesystem::path journal) : lock_file_(journal_lock_path(journal)) {
  check_journal_file(journal);
  // A handful of tries: each lost one means another owner deleted the file between open and flock.
  for (int attempt = 0; attempt < 16; ++attempt) {
    check_journal_file(lock_file_);
    constexpr int kFlags = O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC;
    int descriptor = ::open(lock_file_.c_str(), kFlags | O_CREAT | O_EXCL, 0644);
    const bool created = descriptor >= 0;
    if (!created && errno == EEXIST) {
      descriptor = ::open(lock_file_.c_str(), kFlags);
      if (descriptor < 0 && errno == ENOENT) continue;  // its owner just ended and deleted it
    }
    if (descriptor < 0)
      throw InputError(lock_file_.string() + ": cannot create the resume journal's lock file: " + std::strerror(errno));
    if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      ::close(descriptor);
      if (error == EWOULDBLOCK)
        throw InputError(journal.string() +
                         ": another render of the same output owns this resume journal and is "
                         "still running; wait for it to finish or choose another output");
      throw InputError(lock_file_.string() + ": cannot lock the resume journal: " + std::strerror(error));
    }
    if (is_file_at(descriptor, lock_file_)) {
      descriptor_ = descriptor;
      // A lock file is empty: one left by a killed render goes when this render ends; a file with
      // contents at that name is not rtpro's and stays.
      struct stat taken {};
      removable_ = created || (::fstat(descriptor, &taken) == 0 && taken.st_size == 0);
      return;
    }
    ::close(descriptor);
  }
  throw InputError(lock_file_.string() +
                   ": the resume journal's lock file keeps changing; is another render "
                   "of the same output starting?");
}

JournalOwner::~JournalOwner() {
  // Deleted while still locked, so no other render can hold a lock on it that a third would miss.
  if (removable_ && is_file_at(descriptor_, lock_file_)) ::unlink(lock_file_.c_str());
  ::close(descriptor_);
}

}  // namespace rtpro
