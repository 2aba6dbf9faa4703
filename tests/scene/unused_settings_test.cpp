// The path integrator's controls given to a whitted render are named in one warning.
#include "rtpro/scene/unused_settings.h"

#include <gtest/gtest.h>

#include <string>

namespace rtpro {
namespace unused_settings_test {

TEST(UnusedSettings, PathControlsOfAWhittedRenderAreNamed) {
  RenderSettings render;
  render.integrator = Integrator::kWhitted;
  EXPECT_FALSE(ignored_path_controls_warning(render));
  render.path.clamp_direct = 3.0f;
  const std::string one = ignored_path_controls_warning(render).value_or("");
  EXPECT_NE(one.find("render.clamp_direct is read by the path integrator only"), std::string::npos) << one;
  EXPECT_NE(one.find("--integrator path to use it)"), std::string::npos) << one;
  render.path.max_diffuse_depth = 2;
  render.path.max_volume_depth = 0;
  render.path.filter_glossy = 1.0f;
  const std::string several = ignored_path_controls_warning(render).value_or("");
  EXPECT_NE(several.find("render.max_diffuse_depth, render.max_volume_depth, render.clamp_direct, "
                         "render.filter_glossy are read by the path integrator only"),
            std::string::npos)
      << several;
}

TEST(UnusedSettings, PathRendersAndControlsLeftOffSayNothing) {
  RenderSettings render;
  render.integrator = Integrator::kPath;
  render.path.clamp_indirect = 1.0f;
  render.path.max_glossy_depth = 1;
  EXPECT_FALSE(ignored_path_controls_warning(render));
  render.integrator = Integrator::kWhitted;
  render.path = {};
  render.path.clamp_direct = 0.0f;  // 0 is off, as the controls' defaults
  EXPECT_FALSE(ignored_path_controls_warning(render));
}

}  // namespace unused_settings_test
}  // namespace rtpro
