// Golden-image regression tests: every scene in scenes/ is rendered small (160 pixels wide,
// 4 spp) with each backend, in process, and compared with its reference in tests/references/,
// a native render. The cases are listed from the scenes folder whenever the test binary lists
// its tests (the build relinks it when a scene file is added or removed), so a new scene without a
// reference fails until one is made. Tolerances, measurements and how to regenerate:
// tests/references/README.md.
#include "fetched_meshes.h"
#include "html_report.h"
#include "regression_paths.h"
#include "regression_tolerance.h"
#include "scene_textures.h"
#include "test_paths.h"

#include "rtpro/backend/backend.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/image/image_io.h"
#include "rtpro/render/renderer.h"
#include "rtpro/scene/build_render_scene.h"
#include "rtpro/scene/scene_parser.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace rtpro {
namespace regression_test {

namespace fs = std::filesystem;
using regression::reference_file;
using regression::results_root;
using regression::source_relative;
using regression::Tolerance;
using regression::update_command;

constexpr int kReferenceWidth = 160;  // the height keeps the scene's aspect
constexpr int kReferenceSpp = 4;

struct RegressionCase {
  fs::path scene;
  BackendKind backend;
};

std::vector<RegressionCase> regression_cases() {
  std::vector<RegressionCase> cases;
  for (const fs::path& scene : regression::scene_files())
    for (const BackendKind backend : {BackendKind::kNative, BackendKind::kEmbree}) cases.push_back({scene, backend});
  return cases;
}

// GoogleTest prints the parameter in failure lines; bytes would say nothing.
void PrintTo(const RegressionCase& c, std::ostream* out) {
  *out << c.scene.filename().string() << " with " << backend_name(c.backend);
}

// "demo-native": the failure folder's name; the test name uses '_' (GoogleTest allows no '-').
std::string case_folder(const RegressionCase& c) {
  return regression::scene_name(c.scene) + "-" + std::string(backend_name(c.backend));
}

std::string case_test_name(const testing::TestParamInfo<RegressionCase>& info) {
  std::string name = case_folder(info.param);
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

bool updating_references() {
  const char* value = std::getenv("RTPRO_UPDATE_REFERENCES");
  return value && *value && std::string(value) != "0";
}

struct SmallRender {
  Image image;
  Tolerance tolerance;
};

SmallRender render_small(const fs::path& scene_file, BackendKind backend_kind) {
  const SceneDescription full = parse_scene_file(scene_file);
  const long height = std::max(1L, std::lround(double(kReferenceWidth) * full.camera.height / full.camera.width));
  const SceneDescription small = parse_scene_file(
      scene_file, {"render.spp=" + std::to_string(kReferenceSpp),
                   "camera.resolution=[" + std::to_string(kReferenceWidth) + "," + std::to_string(height) + "]"});
  const RenderScene scene = build_render_scene(small);
  const auto backend = make_backend(backend_kind, scene, BackendOptions{});
  const std::unique_ptr<TextureLookup> textures = regression::open_scene_textures(scene);
  const std::optional<EnvironmentLight> environment = regression::build_scene_environment(scene);
  RenderOptions options;
  options.textures = textures.get();
  options.environment = environment ? &*environment : nullptr;
  return {render_image(scene, *backend, options).image, regression::tolerance_for(backend_kind, scene)};
}

// Rewrites the reference only when a pixel changed, so unchanged references stay byte-identical
// in git (the EXR header carries a date).
void update_reference(const fs::path& scene, const Image& rendered) {
  const fs::path reference = reference_file(scene);
  std::string outcome = "new";
  if (fs::exists(reference)) {
    CompareThresholds identical;
    identical.fail = identical.warn = 0.0f;
    const ImageComparison comparison = compare_images(read_image(reference), rendered, identical);
    if (comparison.passed && comparison.max_error == 0.0) {
      std::cout << source_relative(reference) << ": unchanged" << std::endl;
      return;
    }
    std::ostringstream change;
    if (comparison.incompatibility.empty())
      change << "changed: max error " << comparison.max_error << ", " << comparison.fail_pixels << " pixels differ";
    else change << "changed: " << comparison.incompatibility;
    outcome = change.str();
  }
  fs::create_directories(reference.parent_path());
  ImageWriteOptions options;
  options.metadata = {{"rtpro:scene", source_relative(scene)},
                      {"rtpro:backend", "native"},
                      {"rtpro:spp", std::to_string(kReferenceSpp)}};
  write_image(reference, rendered, options);
  std::cout << source_relative(reference) << ": " << outcome << std::endl;
}

std::string figures_summary(const ImageComparison& c) {
  std::ostringstream text;
  text << "mean error " << c.mean_error << ", RMS " << c.rms_error << ", PSNR " << c.psnr << " dB, max error "
       << c.max_error << " at (" << c.max_x << ", " << c.max_y << ") " << c.max_channel << ", " << c.fail_pixels
       << " of " << c.pixel_count << " pixels over the threshold";
  return text.str();
}

class RegressionTest : public testing::TestWithParam<RegressionCase> {};

TEST_P(RegressionTest, MatchesReference) {
  const RegressionCase& c = GetParam();
  const std::string scene_name = source_relative(c.scene);
  const std::string backend(backend_name(c.backend));

  const auto missing = regression::missing_meshes(c.scene, test::source_dir() / "scripts");
  for (const auto& mesh : missing)
    if (!mesh.fetch_script)
      FAIL() << scene_name << " uses " << mesh.file.string()
             << ", which does not exist and no scripts/fetch-*.sh provides it";
  if (!missing.empty())
    GTEST_SKIP() << scene_name << " needs " << missing.front().file.string()
                 << ", which is fetched, not committed: run " << source_relative(*missing.front().fetch_script);

  if (updating_references()) {
    if (c.backend != BackendKind::kNative) GTEST_SKIP() << "references are native renders";
    update_reference(c.scene, render_small(c.scene, c.backend).image);
    return;
  }

  const fs::path reference_path = reference_file(c.scene);
  if (!fs::exists(reference_path)) FAIL() << "no reference for " << scene_name << ": run " << update_command();
  const SmallRender rendered = render_small(c.scene, c.backend);
  const Image reference = read_image(reference_path);
  const CompareThresholds& thresholds = rendered.tolerance.thresholds;
  const ImageComparison comparison = compare_images(reference, rendered.image, thresholds);
  if (comparison.passed) {
    regression::clear_failure(results_root(), case_folder(c), update_command());
    return;
  }

  nlohmann::json figures = regression::comparison_figures(comparison, thresholds);
  figures["scene"] = scene_name;
  figures["backend"] = backend;
  figures["rule"] = rendered.tolerance.rule;
  figures["reference"] = source_relative(reference_path);
  const fs::path folder = results_root() / case_folder(c);
  regression::write_failure_folder(folder, reference, rendered.image, figures);
  const fs::path report = regression::regenerate_report(results_root(), update_command());
  ADD_FAILURE() << scene_name << " with " << backend << " differs from " << source_relative(reference_path) << " ("
                << rendered.tolerance.rule << " tolerance): " << comparison.verdict << "\n  "
                << figures_summary(comparison) << "\n  images: " << folder.string() << "\n  report: " << report.string()
                << "\n  if the change is intended: " << update_command();
}

INSTANTIATE_TEST_SUITE_P(Scenes, RegressionTest, testing::ValuesIn(regression_cases()), case_test_name);

}  // namespace regression_test
}  // namespace rtpro
