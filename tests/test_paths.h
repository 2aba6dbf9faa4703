#pragma once
// Paths the tests need: the source tree (scenes, fixtures), a scratch folder, the rtpro binary.
#include <filesystem>
#include <string>

namespace rtpro::test {

std::filesystem::path source_dir();
std::filesystem::path scenes_dir();
std::filesystem::path rtpro_executable();
// A fresh, empty folder under the build tree named after the running test.
std::filesystem::path scratch_dir();
// Writes `text` to scratch_dir()/name and returns the path.
std::filesystem::path write_file(const std::string& name, const std::string& text);
// The whole of `file`, byte for byte; empty when it cannot be read.
std::string read_file(const std::filesystem::path& file);

// Whether `scene` refers to meshes fetched by scripts/fetch-dragon.sh (under assets/), and
// whether those have been fetched: tests skip such scenes until they are.
bool uses_fetched_assets(const std::filesystem::path& scene);
bool fetched_assets_present();

}  // namespace rtpro::test
