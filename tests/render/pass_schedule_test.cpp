#include "rtpro/render/pass_schedule.h"

#include <gtest/gtest.h>

namespace rtpro {
namespace pass_schedule_test {

// Passes follow one another without gaps, double up to the step and end at spp.
void expect_covers(const PassSchedule& schedule, int spp) {
  int next = 0;
  for (int p = 0; p < schedule.passes(); ++p) {
    const SampleRange range = schedule.pass(p);
    EXPECT_EQ(range.begin, next);
    EXPECT_GT(range.count(), 0);
    EXPECT_EQ(schedule.samples_through(p), range.end);
    next = range.end;
  }
  EXPECT_EQ(next, spp);
  EXPECT_EQ(schedule.spp(), spp);
}

TEST(PassSchedule, SobolPassesDoubleToAStepOfAboutTheSquareRootOfSpp) {
  const PassSchedule schedule(1024, SamplerKind::kSobol);
  expect_covers(schedule, 1024);
  const int expected[] = {1, 1, 2, 4, 8, 16, 32, 32};
  for (int p = 0; p < 8; ++p) EXPECT_EQ(schedule.pass(p).count(), expected[p]) << "pass " << p;
  EXPECT_EQ(schedule.passes(), 6 + (1024 - 32) / 32);
}

TEST(PassSchedule, EveryPassOfAPowerOfTwoStartsAtAMultipleOfItsSize) {
  // Sobol points are well spread in aligned power-of-two runs.
  for (int spp : {1, 4, 16, 64, 256, 4096, 65536}) {
    const PassSchedule schedule(spp, SamplerKind::kSobol);
    expect_covers(schedule, spp);
    for (int p = 0; p < schedule.passes(); ++p) {
      const SampleRange range = schedule.pass(p);
      EXPECT_EQ(range.count() & (range.count() - 1), 0) << spp << " spp, pass " << p;
      EXPECT_EQ(range.begin % range.count(), 0) << spp << " spp, pass " << p;
      EXPECT_LE(range.count(), 64);
    }
  }
}

TEST(PassSchedule, OddSppEndsWithAShorterPass) {
  const PassSchedule schedule(100, SamplerKind::kSobol);
  expect_covers(schedule, 100);
  EXPECT_EQ(schedule.pass(schedule.passes() - 1).count(), 100 - 96);
}

TEST(PassSchedule, StratifiedSamplesRenderInOnePass) {
  const PassSchedule schedule(48, SamplerKind::kStratified);
  ASSERT_EQ(schedule.passes(), 1);
  EXPECT_EQ(schedule.pass(0).begin, 0);
  EXPECT_EQ(schedule.pass(0).end, 48);
}

}  // namespace pass_schedule_test
}  // namespace rtpro
