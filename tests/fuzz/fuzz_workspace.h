#pragma once
// A private folder for the fuzz targets whose readers take a file name, not bytes: the input is
// written there and read back through the same public loader `rtpro` uses. The folder lives on
// /dev/shm when it exists (no disk I/O per execution) and is removed when the process exits.
#include <filesystem>
#include <string_view>

namespace rtpro::fuzz {

// The folder, created on first use.
const std::filesystem::path& workspace();

// Writes `bytes` to workspace()/name (replacing it) and returns the full path.
std::filesystem::path write_workspace_file(std::string_view name, std::string_view bytes);

// Removes workspace()/name if it exists.
void remove_workspace_file(std::string_view name);

}  // namespace rtpro::fuzz
