#include "rtpro/core/special_file_kind.h"

#include <sys/stat.h>

namespace rtpro {

const char* special_file_kind(mode_t mode) {
  if (S_ISREG(mode)) return "a regular file";
  if (S_ISLNK(mode)) return "a symbolic link";
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "a special file";
}

std::string unreadable_file_problem(const std::filesystem::path& file) {
  struct stat status {};
  if (::stat(file.c_str(), &status) != 0) return "not found";
  if (S_ISREG(status.st_mode)) return {};
  return std::string("is ") + special_file_kind(status.st_mode) + ", not a file";
}

}  // namespace rtpro
