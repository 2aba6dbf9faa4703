#pragma once
// rtpro's plugins (OpenImageIO, OpenVDB, Open MPI) are found beside the executable, as the build
// puts them: through the executable's own path, not the current folder or the library search path,
// so a plugin always comes from the same build as the program that loads it.
#include <filesystem>

namespace rtpro {

// The path of `file_name` in the executable's folder. Throws RuntimeError, saying what could not
// be loaded (`what`, e.g. "the image layer"), when the executable's own path is unknown.
std::filesystem::path plugin_beside_executable(const char* file_name, const char* what);

}  // namespace rtpro
