#include "backend_options.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtpro::cli {
namespace backend_options_test {

// Parses `arguments` (without the program name) into fresh options.
BackendOptions parsed(std::vector<std::string> arguments) {
  CLI::App app;
  BackendOptions options;
  add_embree_options(app, options);
  std::vector<const char*> argv = {"rtpro"};
  for (const std::string& argument : arguments) argv.push_back(argument.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  return options;
}

TEST(BackendOptions, DefaultsAreMediumQualityAndRobustTraversal) {
  const BackendOptions options = parsed({});
  EXPECT_EQ(options.embree_quality, EmbreeBuildQuality::kMedium);
  EXPECT_TRUE(options.embree_robust);
}

TEST(BackendOptions, QualityNamesInAnyCaseBecomeTheEnum) {
  EXPECT_EQ(parsed({"--embree-quality", "low"}).embree_quality, EmbreeBuildQuality::kLow);
  EXPECT_EQ(parsed({"--embree-quality", "HIGH"}).embree_quality, EmbreeBuildQuality::kHigh);
  EXPECT_EQ(parsed({"--embree-quality=Medium"}).embree_quality, EmbreeBuildQuality::kMedium);
}

TEST(BackendOptions, UnknownQualitiesAndTheEnumsNumbersAreRefused) {
  EXPECT_THROW(parsed({"--embree-quality", "ultra"}), CLI::ValidationError);
  EXPECT_THROW(parsed({"--embree-quality", "2"}), CLI::ValidationError);
}

TEST(BackendOptions, RobustTraversalIsAFlagPair) {
  EXPECT_TRUE(parsed({"--embree-robust"}).embree_robust);
  EXPECT_FALSE(parsed({"--no-embree-robust"}).embree_robust);
  EXPECT_THROW(parsed({"--embree-robust", "false"}), CLI::ExtrasError);
}

}  // namespace backend_options_test
}  // namespace rtpro::cli
