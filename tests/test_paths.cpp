#include "test_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

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

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool uses_fetched_assets(const std::filesystem::path& scene) {
  return read_file(scene).find("assets/") != std::string::npos;
}

bool fetched_assets_present() { return std::filesystem::is_regular_file(source_dir() / "assets" / "dragon.obj"); }

}  // namespace rtpro::test
