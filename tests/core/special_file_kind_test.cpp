#include "rtpro/core/special_file_kind.h"

#include "test_paths.h"

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

namespace rtpro {
namespace special_file_kind_test {

std::string kind_of(const std::filesystem::path& path) {
  struct stat status {};
  EXPECT_EQ(::lstat(path.c_str(), &status), 0) << path;
  return special_file_kind(status.st_mode);
}

TEST(SpecialFileKind, NamesWhatTheFileSystemHoldsThere) {
  const auto folder = test::scratch_dir();
  std::ofstream(folder / "file") << "text";
  std::filesystem::create_symlink(folder / "file", folder / "link");
  std::filesystem::create_directory(folder / "dir");
  ASSERT_EQ(::mkfifo((folder / "fifo").c_str(), 0600), 0);

  EXPECT_EQ(kind_of(folder / "file"), "a regular file");
  EXPECT_EQ(kind_of(folder / "link"), "a symbolic link");  // lstat: the link, not its target
  EXPECT_EQ(kind_of(folder / "dir"), "a directory");
  EXPECT_EQ(kind_of(folder / "fifo"), "a FIFO (named pipe)");
  EXPECT_EQ(kind_of("/dev/null"), "a character device");
}

TEST(SpecialFileKind, NamesABoundSocket) {
  // A socket path must fit sun_path (108 bytes), which the scratch folder may not.
  const std::string path = "/tmp/rtpro-kind-" + std::to_string(::getpid()) + ".sock";
  ::unlink(path.c_str());
  const int descriptor = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(descriptor, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
  ASSERT_EQ(::bind(descriptor, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(kind_of(path), "a socket");
  ::close(descriptor);
  ::unlink(path.c_str());
}

// Kinds a test cannot make without privileges, and one no POSIX file system has.
TEST(SpecialFileKind, NamesBlockDevicesAndUnknownKinds) {
  EXPECT_STREQ(special_file_kind(S_IFBLK | 0660), "a block device");
  EXPECT_STREQ(special_file_kind(0), "a special file");
}

}  // namespace special_file_kind_test
}  // namespace rtpro
