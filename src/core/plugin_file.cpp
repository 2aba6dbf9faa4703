#include "rtpro/core/plugin_file.h"

#include "rtpro/core/error.h"

#include <dlfcn.h>

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

void* open_plugin_entry(const std::filesystem::path& file, const char* entry_point, const char* what) {
  void* handle = dlopen(file.c_str(), RTLD_LAZY | RTLD_LOCAL);
  if (!handle)
    throw RuntimeError(std::string("cannot load ") + what + ": " + dlerror() + "; rtpro needs " +
                       file.filename().string() + " from its own build in the folder of the executable");
  return dlsym(handle, entry_point);
}

void refuse_stale_plugin(const std::filesystem::path& file, const char* version, const char* what) {
  throw RuntimeError(std::string("cannot load ") + what + ": " + file.string() +
                     " is not the plugin of this rtpro build (" + version + "); rebuild rtpro");
}

}  // namespace rtpro
