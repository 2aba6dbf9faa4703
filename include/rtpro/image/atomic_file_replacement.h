#pragma once
// Replacing a file so that readers see either its old contents or the complete new ones: the new
// file is written under a temporary name in the same folder (rename is only atomic within one
// file system), flushed to disk, then renamed over the target. A process killed mid-write leaves
// the old file intact and at worst a stray ".<name>.tmp-*" file.
#include <filesystem>

namespace rtpro {

class AtomicFileReplacement {
 public:
  // Throws RuntimeError naming the folder when it does not exist, is not a folder or is not
  // writable.
  explicit AtomicFileReplacement(std::filesystem::path target);
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFileReplacement();
  AtomicFileReplacement(const AtomicFileReplacement&) = delete;
  AtomicFileReplacement& operator=(const AtomicFileReplacement&) = delete;

  // ".<stem>.tmp-<pid>-<random><extension>": the extension stays last because OpenImageIO picks
  // the format from it.
  const std::filesystem::path& temporary_path() const { return temporary_; }

  // Flushes the temporary file to disk and renames it over the target. Throws RuntimeError.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  bool committed_ = false;
};

}  // namespace rtpro
