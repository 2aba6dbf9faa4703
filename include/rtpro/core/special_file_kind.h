#pragma once
// What a path names when it is not a regular file, for the messages that refuse it: rtpro reads
// and replaces only regular files, since a FIFO or a device would block or never end, and a link or
// a folder is not the caller's to overwrite. One wording for the scene reader, the mesh mapper,
// the atomic writer and the resume journal.
#include <sys/types.h>

#include <filesystem>
#include <string>

namespace rtpro {

// "a directory", "a FIFO (named pipe)", "a symbolic link"... with its article, to follow "it is";
// "a regular file" for one, and "a special file" for a kind this list lacks. The mode is stat's
// st_mode (lstat's for the link to show).
const char* special_file_kind(mode_t mode);

// Why `file` (symbolic links followed) cannot be read as a file, to follow its name in a message:
// "not found", "is a directory, not a file", "is a FIFO (named pipe), not a file"; empty when it
// is a regular file.
std::string unreadable_file_problem(const std::filesystem::path& file);

}  // namespace rtpro
