// One render at a time owns a resume journal (issue 28: two renders of one output deleted each
// other's journal).
#include "rtpro/job/journal_owner.h"

#include "rtpro/core/error.h"
#include "test_paths.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <thread>

namespace rtpro {
namespace journal_owner_test {

TEST(JournalOwner, SecondOwnerIsRefusedUntilTheFirstEnds) {
  const auto journal = test::scratch_dir() / "out.exr.rtpro-journal";
  {
    const JournalOwner first(journal);
    EXPECT_TRUE(std::filesystem::exists(journal_lock_path(journal)));
    // Another thread stands for another process: flock locks belong to open files, not processes.
    std::thread second([&] {
      try {
        const JournalOwner owner(journal);
        ADD_FAILURE() << "a second render took the journal";
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("another render"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(journal.string()), std::string::npos) << e.what();
      }
    });
    second.join();
  }
  EXPECT_FALSE(std::filesystem::exists(journal_lock_path(journal))) << "the owner removes its lock file";
  const JournalOwner again(journal);
}

TEST(JournalOwner, LockFileLeftByAKilledRenderIsTakenOver) {
  const auto journal = test::scratch_dir() / "out.exr.rtpro-journal";
  test::write_file(journal_lock_path(journal).filename().string(), "");
  const JournalOwner owner(journal);
}

TEST(JournalOwner, FifoAtTheLockFileOrJournalIsRefused) {
  const auto folder = test::scratch_dir();
  const auto journal = folder / "a.rtpro-journal";
  ASSERT_EQ(::mkfifo(journal_lock_path(journal).c_str(), 0600), 0);
  EXPECT_THROW(JournalOwner{journal}, InputError);
  const auto other = folder / "b.rtpro-journal";
  ASSERT_EQ(::mkfifo(other.c_str(), 0600), 0);
  EXPECT_THROW(JournalOwner{other}, InputError);
  EXPECT_EQ(std::filesystem::symlink_status(other).type(), std::filesystem::file_type::fifo);
}

}  // namespace journal_owner_test
}  // namespace rtpro
