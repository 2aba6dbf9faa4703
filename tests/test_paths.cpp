#include "test_paths.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sys/wait.h>
#include <unistd.h>

namespace rtpro::test {

std::filesystem::path source_dir() { return RTPRO_SOURCE_DIR; }
std::filesystem::path scenes_dir() { return source_dir() / "scenes"; }
std::filesystem::path rtpro_executable() { return RTPRO_EXECUTABLE; }

namespace {

// build/test_scratch/<suite>.<test> of the running test ('/' of parameterised names replaced).
std::filesystem::path test_folder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "no_test";
  for (char& c : name)
    if (c == '/') c = '_';
  return std::filesystem::path(RTPRO_BINARY_DIR) / "test_scratch" / name;
}

}  // namespace

std::filesystem::path scratch_dir() {
  const auto dir = test_folder();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto path = test_folder() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

bool uses_fetched_assets(const std::filesystem::path& scene) {
  std::ifstream in(scene);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return text.find("assets/") != std::string::npos;
}

bool fetched_assets_present() { return std::filesystem::is_regular_file(source_dir() / "assets" / "dragon.obj"); }

int run_command(const std::string& command_line, std::string* output) {
  const std::string full = command_line + " 2>&1";
  FILE* pipe = popen(full.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buffer{};
  std::string text;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) text += buffer.data();
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string rtpro_command(const std::string& args) { return rtpro_executable().string() + " " + args; }

std::string run_rtpro(const std::string& args, int code) {
  std::string out;
  EXPECT_EQ(run_command(rtpro_command(args), &out), code) << args << "\n" << out;
  return out;
}

pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

}  // namespace rtpro::test
