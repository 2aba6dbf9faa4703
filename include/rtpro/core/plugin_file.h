#pragma once
// rtpro's plugins (OpenImageIO, OpenVDB, Open MPI) are found beside the executable, as the build
// puts them: through the executable's own path, not the current folder or the library search path,
// so a plugin always comes from the same build as the program that loads it.
#include <filesystem>

namespace rtpro {

// The path of `file_name` in the executable's folder. Throws RuntimeError, saying what could not
// be loaded (`what`, e.g. "the image layer"), when the executable's own path is unknown.
std::filesystem::path plugin_beside_executable(const char* file_name, const char* what);

// Opens the plugin `file` and returns the address of its `entry_point` (null when it has none).
// RTLD_LOCAL keeps the plugin's libraries' symbols out of the global scope; RTLD_LAZY binds its
// calls on first use. The handle is never closed: objects and exceptions the plugin makes may
// outlive any one call. Throws RuntimeError naming `what` and the file when it does not load.
void* open_plugin_entry(const std::filesystem::path& file, const char* entry_point, const char* what);

}  // namespace rtpro
