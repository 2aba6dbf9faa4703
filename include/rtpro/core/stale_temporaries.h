#pragma once
// Temporary files named after the process that writes them, "<prefix>PID-N", so that two
// processes (or two threads) writing the same target never share one, and what a killed process
// left behind can be told from what a live one is still writing. The atomic file writer, the
// resume journal, `-o -`'s image and the decoded textures' folder all name their temporaries this
// way.
#include <filesystem>
#include <string>
#include <string_view>

namespace rtpro {

// "<prefix>PID-N" for this process, N unique within it.
std::string owned_temporary_name(std::string_view prefix);

// A new, empty regular file "<folder>/<prefix>PID-N" of this process, open for writing. Created
// with O_EXCL | O_NOFOLLOW: a file or link already at a name (planted there, or left by an earlier
// process with the same PID) is neither written through nor removed; the next N is taken. Returns
// the descriptor and sets `created`; -1 with errno set when no name would do.
int create_owned_temporary(const std::filesystem::path& folder, std::string_view prefix,
                           std::filesystem::path& created);

// Removes the files (and folders, with their contents) in `folder` named "<prefix>PID-…" whose
// process is no longer running. A PID
// reused by another process keeps its file until that process ends too; symbolic links and
// names that do not parse are left alone; a folder that cannot be listed is left as it is.
void remove_stale_temporaries(const std::filesystem::path& folder, std::string_view prefix);

}  // namespace rtpro
