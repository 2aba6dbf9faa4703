#pragma once
// One render at a time owns a resume journal. Without an owner, two renders of one output replace
// each other's journal and the first to finish deletes it, so the other can no longer be resumed.
// The owner holds an exclusive flock(2) on a lock file beside the journal (JOURNAL.lock: the
// journal itself is replaced by rename, so a lock on it would not outlive a compaction) for the
// whole render; the lock goes with the process, however it ends.
#include <filesystem>

namespace rtpro {

// "out.exr.rtpro-journal" → "out.exr.rtpro-journal.lock".
std::filesystem::path journal_lock_path(const std::filesystem::path& journal);

class JournalOwner {
 public:
  // Takes the lock without waiting. Throws InputError naming the journal when another render owns
  // it, or when the journal or its lock file is not a regular file (check_journal_file).
  explicit JournalOwner(std::filesystem::path journal);
  // Deletes the lock file (when this owner created it, or took over an empty one a killed render
  // left) and releases the lock.
  ~JournalOwner();
  JournalOwner(const JournalOwner&) = delete;
  JournalOwner& operator=(const JournalOwner&) = delete;

 private:
  std::filesystem::path lock_file_;
  int descriptor_ = -1;
  bool removable_ = false;
};

}  // namespace rtpro
