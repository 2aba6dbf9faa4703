#pragma once
// rtpro's plugins (OpenImageIO, OpenVDB, Open MPI) are found beside the executable, as the build
// puts them: through the executable's own path, not the current folder or the library search path,
// so a plugin always comes from the same build as the program that loads it.
#include <filesystem>
#include <string_view>

namespace rtpro {

// The path of `file_name` in the executable's folder. Throws RuntimeError, saying what could not
// be loaded (`what`, e.g. "the image layer"), when the executable's own path is unknown.
std::filesystem::path plugin_beside_executable(const char* file_name, const char* what);

// Opens the plugin `file` and returns the address of its `entry_point` (null when it has none).
// RTLD_LOCAL keeps the plugin's libraries' symbols out of the global scope; RTLD_LAZY binds its
// calls on first use. The handle is never closed: objects and exceptions the plugin makes may
// outlive any one call. Throws RuntimeError naming `what` and the file when it does not load.
void* open_plugin_entry(const std::filesystem::path& file, const char* entry_point, const char* what);

// Throws RuntimeError saying that `file` is not the plugin of this build (`version`).
[[noreturn]] void refuse_stale_plugin(const std::filesystem::path& file, const char* version, const char* what);

// The table a plugin's entry point (a function of no arguments) returns, checked to come from the
// same build as its caller: its `abi_version` must be `abi` and its `rtpro_version` `version`.
template <class Table>
const Table* open_plugin_table(const std::filesystem::path& file, const char* entry_point, int abi, const char* version,
                               const char* what) {
  using Entry = const Table* (*)();
  const auto entry = reinterpret_cast<Entry>(open_plugin_entry(file, entry_point, what));
  const Table* table = entry ? entry() : nullptr;
  if (!table || table->abi_version != abi || std::string_view(table->rtpro_version) != version)
    refuse_stale_plugin(file, version, what);
  return table;
}

}  // namespace rtpro
