// Ray counts by kind (ray_counts.h): the names statistics use, sums and totals.
#include "rtpro/render/ray_counts.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace ray_counts_test {

// --stats-json's keys under `rays`, which benchmarks read.
TEST(RayCounts, EveryKindHasItsStatisticsName) {
  std::string names;
  for (const RayKind kind : kRayKinds) names += std::string(ray_kind_name(kind)) + " ";
  EXPECT_EQ(names, "camera shadow reflection refraction ");
}

TEST(RayCounts, SumsAddKindByKindAndTheTotalCountsEveryKind) {
  RayCounts a;
  a[RayKind::kCamera] = 1;
  a[RayKind::kRefraction] = 4;
  RayCounts b = {10, 20, 30, 40};
  b += a;
  EXPECT_EQ(b[RayKind::kCamera], 11u);
  EXPECT_EQ(b[RayKind::kShadow], 20u);
  EXPECT_EQ(b[RayKind::kReflection], 30u);
  EXPECT_EQ(b[RayKind::kRefraction], 44u);
  EXPECT_EQ(b.total(), 105u);
}

}  // namespace ray_counts_test
}  // namespace rtpro
