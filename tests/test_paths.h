#pragma once
// Paths the tests need: the source tree (scenes, fixtures), a scratch folder, the rtpro binary.
#include <sys/types.h>

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

// Whether `scene` refers to meshes fetched by scripts/fetch-dragon.sh (under assets/), and
// whether those have been fetched: tests skip such scenes until they are.
bool uses_fetched_assets(const std::filesystem::path& scene);
bool fetched_assets_present();

// Runs a shell command line; returns its exit code, and stderr+stdout in `output`.
int run_command(const std::string& command_line, std::string* output = nullptr);

// The rtpro binary followed by `args`: a command line for run_command.
std::string rtpro_command(const std::string& args);
// Runs rtpro with `args` and expects exit code `code` (a mismatch fails the test, showing the
// arguments and the output); returns stderr+stdout.
std::string run_rtpro(const std::string& args, int code);

// A PID that is certainly not running: a child that has exited and been reaped.
pid_t dead_pid();

}  // namespace rtpro::test
