#include "rtpro/core/stale_temporaries.h"

#include "test_commands.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <string>

namespace rtpro {
namespace stale_temporaries_test {

TEST(StaleTemporaries, NamesAreThisProcesssAndNeverRepeat) {
  const std::string first = owned_temporary_name("x.tmp-");
  const std::string second = owned_temporary_name("x.tmp-");
  EXPECT_EQ(first.rfind("x.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << first;
  EXPECT_NE(first, second);
}

// Only names of this prefix whose process is gone go; live processes', other prefixes', names
// that do not parse and symbolic links stay.
TEST(StaleTemporaries, OnlyDeadProcessesFilesOfThePrefixAreRemoved) {
  const auto folder = test::scratch_dir();
  const std::string dead = std::to_string(test::dead_pid());
  const std::string live = std::to_string(::getppid());
  for (const std::string& name : {"j.tmp-" + dead + "-0", "j.tmp-" + live + "-1", "k.tmp-" + dead + "-0",
                                  std::string("j.tmp-x-1"), "j.tmp-" + dead})
    std::ofstream(folder / name) << "left";
  std::filesystem::create_symlink(folder / "k.tmp-" / "nowhere", folder / ("j.tmp-" + dead + "-7"));
  remove_stale_temporaries(folder, "j.tmp-");
  EXPECT_FALSE(std::filesystem::exists(folder / ("j.tmp-" + dead + "-0")));
  for (const std::string& kept :
       {"j.tmp-" + live + "-1", "k.tmp-" + dead + "-0", std::string("j.tmp-x-1"), "j.tmp-" + dead})
    EXPECT_TRUE(std::filesystem::exists(folder / kept)) << kept;
  EXPECT_TRUE(std::filesystem::is_symlink(folder / ("j.tmp-" + dead + "-7")));
  remove_stale_temporaries(folder / "missing", "j.tmp-");  // nothing to list: nothing happens
}

}  // namespace stale_temporaries_test
}  // namespace rtpro
