#include "rtpro/image/output_check.h"

#include "rtpro/core/error.h"
#include "test_paths.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace rtpro {
namespace output_check_test {

// Every format name and extension OpenImageIO knows, readable or writable.
std::vector<std::string> every_known_name() {
  std::vector<std::string> names;
  std::istringstream formats(OIIO::get_string_attribute("extension_list"));
  std::string format;
  while (std::getline(formats, format, ';')) {
    const auto colon = format.find(':');
    names.push_back(format.substr(0, colon));
    std::istringstream extensions(format.substr(colon + 1));
    std::string extension;
    while (std::getline(extensions, extension, ',')) names.push_back(extension);
  }
  return names;
}

bool check_accepts(const std::filesystem::path& file) {
  try {
    check_image_output(file);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// The check answers from a list generated at build time; it must give OpenImageIO's own answer.
TEST(OutputCheck, AcceptsExactlyWhatOpenImageIoCanWrite) {
  const auto folder = test::scratch_dir();
  const auto names = every_known_name();
  ASSERT_GT(names.size(), 20u);
  int writable = 0;
  for (const std::string& name : names) {
    const auto file = folder / ("image." + name);
    const bool oiio_writes = OIIO::ImageOutput::create(file.string()) != nullptr;
    OIIO::geterror();
    EXPECT_EQ(check_accepts(file), oiio_writes) << file;
    writable += oiio_writes;
  }
  EXPECT_GT(writable, 5);
  EXPECT_LT(writable, static_cast<int>(names.size())) << "camera raw formats, for one, are read-only";
}

TEST(OutputCheck, ExtensionIsCaseInsensitive) {
  const auto folder = test::scratch_dir();
  EXPECT_NO_THROW(check_image_output(folder / "image.PNG"));
  EXPECT_NO_THROW(check_image_output(folder / "image.Exr"));
}

TEST(OutputCheck, UnknownMissingOrReadOnlyFormatsAreInputErrors) {
  const auto folder = test::scratch_dir();
  EXPECT_THROW(check_image_output(folder / "image.xyz"), InputError);
  EXPECT_THROW(check_image_output(folder / "image"), InputError);
  EXPECT_THROW(check_image_output(folder / "image."), InputError);
  EXPECT_THROW(check_image_output(folder / "image.cr2"), InputError);  // camera raw: OpenImageIO only reads it
  EXPECT_THROW(check_image_output(""), InputError);
}

TEST(OutputCheck, MissingFolderIsARuntimeError) {
  EXPECT_THROW(check_image_output(test::scratch_dir() / "missing" / "image.png"), RuntimeError);
}

// /proc passes root's writability check but takes no new file: refused before a render, not after.
TEST(OutputCheck, AFolderThatTakesNoNewFileIsARuntimeError) {
  if (!std::filesystem::is_directory("/proc/self")) GTEST_SKIP() << "no /proc";
  EXPECT_THROW(check_image_output("/proc/rtpro-output-check.png"), RuntimeError);
}

TEST(OutputCheck, LeavesNothingBehindInAWritableFolder) {
  const auto folder = test::scratch_dir();
  check_image_output(folder / "image.png");
  EXPECT_TRUE(std::filesystem::is_empty(folder));
}

}  // namespace output_check_test
}  // namespace rtpro
