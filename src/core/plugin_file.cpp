#include "rtpro/core/plugin_file.h"

#include "rtpro/core/error.h"

#include <string>
#include <system_error>

namespace rtpro {

std::filesystem::path plugin_beside_executable(const char* file_name, const char* what) {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw RuntimeError(std::string("cannot load ") + what +
                       ": cannot find rtpro's own folder (/proc/self/exe: " + error.message() + ")");
  return executable.parent_path() / file_name;
}

}  // namespace rtpro
