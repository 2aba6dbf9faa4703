#pragma once
// The one way rtpro writes a file (images, diff images, statistics JSON, reports): readers see
// either the old contents or the complete new ones, never a mix, a truncation or nothing.
//
// - The new contents go to a temporary file beside the target (rename is atomic only within one
//   file system), named ".NAME.rtpro-tmp-PID-N" so that it is hidden, recognisably rtpro's, and
//   says which process owns it. It is created with O_EXCL | O_NOFOLLOW (a symbolic link planted
//   at that predictable name is never followed: the next name is taken), and only the file
//   created is renamed over the target.
// - Every write, fsync and close is checked; a full disk or any I/O error is a RuntimeError
//   (exit 1), the temporary file is removed and the target keeps its old contents.
// - Only regular files are replaced. A symlink, device node, FIFO, socket or folder at the
//   target's path is refused (as root, --stats-json /dev/null would otherwise replace the device).
// - Temporaries of earlier runs that were killed (SIGKILL, power loss) are removed the next time
//   anything writes the same target: a temporary whose PID is no longer running is stale.
// - Two processes writing the same target at once each rename a complete file of their own; the
//   target ends as one of them, never a mix.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rtpro {

// Throws RuntimeError naming the file when the target exists and is not a regular file, or its
// folder does not exist or is not writable. Cheap: callers use it to fail before a long render.
void check_replaceable(const std::filesystem::path& target);

// Writes `bytes` to `target` through a temporary file as described above.
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes);

// For writers that need a path of their own (OpenImageIO writing a format it cannot write to
// memory): write the temporary_path(), then commit(). Destroying it without commit() removes the
// temporary file.
class AtomicFileReplacement {
 public:
  // Checks the target (check_replaceable) and removes stale temporaries of it.
  explicit AtomicFileReplacement(std::filesystem::path target);
  ~AtomicFileReplacement();
  AtomicFileReplacement(const AtomicFileReplacement&) = delete;
  AtomicFileReplacement& operator=(const AtomicFileReplacement&) = delete;

  // The temporary file, created empty by the constructor, and a descriptor open for writing it.
  const std::filesystem::path& temporary_path() const { return temporary_; }
  int descriptor() const { return descriptor_; }
  const std::filesystem::path& target() const { return target_; }

  // Flushes the temporary file to disk, checks it is still the file created and the target is
  // still replaceable, renames the temporary over the target and flushes the folder. Throws
  // RuntimeError.
  void commit();

 private:
  void create_temporary();

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int descriptor_ = -1;
  std::uint64_t device_ = 0, inode_ = 0;
  bool committed_ = false;
};

// The temporary-file prefix for `target`: ".NAME.rtpro-tmp-" (what stale-file cleaning matches).
std::string temporary_prefix(const std::filesystem::path& target);

}  // namespace rtpro
