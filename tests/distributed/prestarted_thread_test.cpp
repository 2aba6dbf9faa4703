#include "rtpro/distributed/prestarted_thread.h"

#include "rtpro/core/error.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace rtpro {
namespace prestarted_thread_test {

TEST(PrestartedThread, RunsItsTaskOnTheThreadCreatedBefore) {
  const std::thread::id caller = std::this_thread::get_id();
  std::thread::id ran_on;
  PrestartedThread thread;
  thread.run([&] { ran_on = std::this_thread::get_id(); });
  thread.join();
  EXPECT_NE(ran_on, std::thread::id());
  EXPECT_NE(ran_on, caller);
}

TEST(PrestartedThread, EndsWithoutATaskAndRunsOnlyOne) {
  { PrestartedThread unused; }  // must not hang
  std::atomic<int> runs = 0;
  PrestartedThread thread;
  thread.run([&] { ++runs; });
  EXPECT_THROW(thread.run([&] { ++runs; }), RuntimeError);
  thread.join();
  thread.join();  // a second join is harmless
  EXPECT_EQ(runs.load(), 1);
}

}  // namespace prestarted_thread_test
}  // namespace rtpro
