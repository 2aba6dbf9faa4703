// write_image when it cannot write: nothing is created, an existing file is kept, no temporary file is left.
#include "rtpro/image/image_io.h"

#include "image_io_fixtures.h"
#include "rtpro/core/error.h"
#include "test_fixtures.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <string>
#include <sys/resource.h>
#include <vector>

namespace rtpro::test {
namespace image_write_failures_test {

namespace fs = std::filesystem;

std::vector<std::string> folder_listing(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ImageIo, UnknownExtensionIsAnInputErrorAndCreatesNothing) {
  const auto folder = test::scratch_dir();
  const std::string message =
      error_message_of<InputError>([&] { write_image(folder / "picture.xyz", uniform_image(2, 2, 0.5f), {}); });
  EXPECT_NE(message.find(".xyz"), std::string::npos) << message;
  EXPECT_TRUE(folder_listing(folder).empty());
  EXPECT_THROW(write_image(folder / "no_extension", uniform_image(2, 2, 0.5f), {}), InputError);
  EXPECT_TRUE(folder_listing(folder).empty());
}

TEST(ImageIo, MissingFolderIsARuntimeErrorNamingIt) {
  const auto folder = test::scratch_dir() / "not" / "there";
  const std::string message =
      error_message_of<RuntimeError>([&] { write_image(folder / "out.png", uniform_image(2, 2, 0.5f), {}); });
  EXPECT_NE(message.find(folder.string()), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(folder));
}

// /proc reports no free blocks because it has no blocks at all: its folders are not "full", the
// file cannot be created there (root passes the writability check, others are told it is not
// writable).
TEST(ImageIo, AFolderOnAFileSystemWithoutBlocksIsNotCalledFull) {
  if (!fs::is_directory("/proc/self")) GTEST_SKIP() << "no /proc";
  const fs::path target = "/proc/rtpro-image-write-test.png";
  const std::string message =
      error_message_of<RuntimeError>([&] { write_image(target, uniform_image(2, 2, 0.5f), {}); });
  EXPECT_NE(message.find(target.string()), std::string::npos) << message;
  EXPECT_EQ(message.find("full"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(target));
}

TEST(ImageIo, EmptyImageIsRefusedWithoutTouchingTheDisk) {
  const auto folder = test::scratch_dir();
  EXPECT_THROW(write_image(folder / "empty.exr", Image(0, 4), {}), RuntimeError);
  EXPECT_TRUE(folder_listing(folder).empty());
}

TEST(ImageIo, OverwritingReplacesTheFileAndLeavesNoTemporaryFile) {
  const auto folder = test::scratch_dir();
  write_image(folder / "out.exr", uniform_image(2, 2, 0.25f), {});
  write_image(folder / "out.exr", uniform_image(3, 1, 0.75f), {});
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"out.exr"});
  EXPECT_EQ(read_image(folder / "out.exr").data, uniform_image(3, 1, 0.75f).data);
}

TEST(ImageIo, BadViewLeavesTheExistingFileUntouched) {
  const auto folder = test::scratch_dir();
  write_image(folder / "out.png", uniform_image(2, 2, 0.5f), {});
  const std::string before = read_file(folder / "out.png");
  ImageWriteOptions options;
  options.view = "No Such View";
  EXPECT_THROW(write_image(folder / "out.png", uniform_image(2, 2, 0.9f), options), InputError);
  EXPECT_EQ(read_file(folder / "out.png"), before);
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"out.png"});
}

// A failure in the middle of writing the pixels: the process may not grow any file past a few
// kilobytes (with SIGXFSZ ignored, write() then fails with EFBIG). Works as root too, unlike a
// read-only folder.
TEST(ImageIo, FailedWriteKeepsTheOldFileAndRemovesTheTemporaryOne) {
  const auto folder = test::scratch_dir();
  const auto target = folder / "render.exr";
  write_image(target, uniform_image(4, 4, 0.5f), {});
  const std::string good = read_file(target);
  ASSERT_LT(good.size(), 4096u);

  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit previous_limit{};
  ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &previous_limit), 0);
  rlimit small_limit = previous_limit;
  small_limit.rlim_cur = 4096;
  ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small_limit), 0);
  std::string message;
  try {
    write_image(target, varied_image(256, 256), {});  // about 700 kB of incompressible floats
  } catch (const RuntimeError& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &previous_limit);
  std::signal(SIGXFSZ, previous_handler);

  EXPECT_NE(message.find(target.string()), std::string::npos) << "expected a RuntimeError naming the file";
  EXPECT_EQ(read_file(target), good);
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"render.exr"});
}

TEST(ImageIo, FailedRenameRemovesTheTemporaryFile) {
  const auto folder = test::scratch_dir();
  fs::create_directories(folder / "taken.png" / "inside");  // a non-empty folder cannot be replaced
  EXPECT_THROW(write_image(folder / "taken.png", uniform_image(2, 2, 0.5f), {}), RuntimeError);
  EXPECT_EQ(folder_listing(folder), std::vector<std::string>{"taken.png"});
  EXPECT_TRUE(fs::is_directory(folder / "taken.png" / "inside"));
}

}  // namespace image_write_failures_test
}  // namespace rtpro::test
