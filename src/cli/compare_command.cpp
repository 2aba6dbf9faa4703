// `rtpro compare REFERENCE TEST`: numerical image comparison for regression tests.
// Exit codes: 0 within tolerance; 1 outside it, including images of different size or channels
// (a real regression, not a usage mistake); 2 for an unreadable file or bad options.
// Warnings never change the exit code; they are reported.
#include "command.h"
#include "output_target.h"
#include "rtpro/core/error.h"
#include "rtpro/image/diff_image.h"
#include "rtpro/image/image_compare.h"
#include "rtpro/image/image_io.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

namespace rtpro::cli {

namespace {

struct CompareCommandOptions {
  std::string reference;
  std::string test;
  CompareThresholds thresholds;
  std::string diff;
  bool json = false;
};

std::string comma_separated(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ",") + name;
  return text;
}

// The float's shortest decimal form, so that --fail 1e-6 is reported as 1e-06, not 9.99999997e-07.
double as_decimal(float value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::strtod(std::string(text, end).c_str(), nullptr);
}

// CLI::NonNegativeNumber's message prints the largest double in full.
const CLI::Validator kNonNegative(
    [](const std::string& text) {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      return (end != text.c_str() && *end == '\0' && value >= 0.0) ? std::string()
                                                                   : "must be a number >= 0, got " + text;
    },
    "NONNEGATIVE");

std::string percent_of_pixels(std::size_t pixels, const ImageComparison& comparison) {
  std::ostringstream text;
  text << pixels << " pixels ("
       << (comparison.pixel_count ? 100.0 * double(pixels) / double(comparison.pixel_count) : 0.0) << "%)";
  return text.str();
}

std::string joined_numbers(const std::vector<double>& values) {
  std::ostringstream text;
  for (std::size_t i = 0; i < values.size(); ++i) text << (i ? " " : "") << values[i];
  return text.str();
}

void print_report(const CompareCommandOptions& o, const Image& reference, const ImageComparison& c) {
  std::cout << "reference   " << o.reference << " (" << reference.width << "x" << reference.height << ", "
            << comma_separated(reference.channels) << ")\n"
            << "test        " << o.test << "\n";
  if (c.incompatibility.empty()) {
    std::cout << "mean error  " << c.mean_error << "\n"
              << "RMS error   " << c.rms_error << "\n"
              << "PSNR        " << c.psnr << (std::isinf(c.psnr) ? "" : " dB") << "\n"
              << "relMSE      " << c.rel_mse << "\n"
              << "means       reference " << joined_numbers(c.reference_means) << ", test "
              << joined_numbers(c.test_means) << "\n"
              << "max error   " << c.max_error << " at x=" << c.max_x << " y=" << c.max_y << " channel "
              << c.max_channel << "\n"
              << "warn        " << percent_of_pixels(c.warn_pixels, c) << " over " << o.thresholds.warn << "\n"
              << "fail        " << percent_of_pixels(c.fail_pixels, c) << " over " << o.thresholds.fail
              << " (allowed: " << o.thresholds.fail_percent << "%)\n";
    if (c.nan_pixels_reference || c.nan_pixels_test || c.nonfinite_mismatch_pixels)
      std::cout << "NaN pixels  reference " << c.nan_pixels_reference << ", test " << c.nan_pixels_test << "; "
                << c.nonfinite_mismatch_pixels << " pixels non-finite in only one image\n";
    if (!o.diff.empty()) std::cout << "diff image  " << o.diff << "\n";
  }
  std::cout << "verdict     " << (c.passed ? "PASS: " : "FAIL: ") << c.verdict << "\n";
}

void print_json(const CompareCommandOptions& o, const Image& reference, const ImageComparison& c) {
  // nlohmann::json writes NaN and infinity as null: an identical pair has "psnr": null.
  nlohmann::json report = {
      {"reference", o.reference},
      {"test", o.test},
      {"passed", c.passed},
      {"verdict", c.verdict},
      {"thresholds",
       {{"fail", as_decimal(o.thresholds.fail)},
        {"warn", as_decimal(o.thresholds.warn)},
        {"fail_percent", o.thresholds.fail_percent},
        {"max_mean_error", o.thresholds.max_mean_error ? nlohmann::json(*o.thresholds.max_mean_error) : nullptr}}},
  };
  if (!c.incompatibility.empty()) {
    report["incompatibility"] = c.incompatibility;
  } else {
    report.update({
        {"width", c.width},
        {"height", c.height},
        {"channels", reference.channels},
        {"pixels", c.pixel_count},
        {"mean_error", c.mean_error},
        {"rms_error", c.rms_error},
        {"psnr", c.psnr},
        {"rel_mse", c.rel_mse},
        {"means", {{"reference", c.reference_means}, {"test", c.test_means}}},
        {"max_error", c.max_error},
        {"max_error_at", {{"x", c.max_x}, {"y", c.max_y}, {"channel", c.max_channel}}},
        {"warn_pixels", c.warn_pixels},
        {"fail_pixels", c.fail_pixels},
        {"nan_pixels", {{"reference", c.nan_pixels_reference}, {"test", c.nan_pixels_test}}},
        {"nonfinite_mismatch_pixels", c.nonfinite_mismatch_pixels},
    });
    if (!o.diff.empty()) report["diff"] = o.diff;
  }
  std::cout << report.dump(2) << "\n";
}

int run_compare(CompareCommandOptions o) {
  check_output_is_distinct({"--diff", o.diff}, {{"the reference", o.reference}, {"the test image", o.test}});
  const Image reference = read_image(o.reference);
  const Image test = read_image(o.test);
  const ImageComparison comparison = compare_images(reference, test, o.thresholds);
  if (!o.diff.empty()) {
    if (comparison.incompatibility.empty()) {
      write_diff_image(o.diff, reference, test, o.thresholds.fail);
    } else {
      std::cerr << "rtpro: no diff image: the images cannot be compared pixel by pixel\n";
      o.diff.clear();
    }
  }
  if (o.json) print_json(o, reference, comparison);
  else print_report(o, reference, comparison);
  return comparison.passed ? kExitOk : kExitRuntimeFailure;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto options = std::make_shared<CompareCommandOptions>();
  auto& thresholds = options->thresholds;
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare a test image with a reference; exit 0 within tolerance, 1 outside, 2 unreadable");
  cmd->add_option("reference", options->reference, "Reference image")->required();
  cmd->add_option("test", options->test, "Image to check against the reference")->required();
  cmd->add_option("--fail", thresholds.fail, "A pixel fails when a channel differs by more than this")
      ->check(kNonNegative)
      ->capture_default_str();
  cmd->add_option("--warn", thresholds.warn, "A pixel warns when a channel differs by more than this")
      ->check(kNonNegative)
      ->capture_default_str();
  cmd->add_option("--fail-percent", thresholds.fail_percent, "Percent of pixels allowed to fail")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  cmd->add_option("--max-mean-error", thresholds.max_mean_error, "Also fail when the mean error is higher")
      ->check(kNonNegative);
  cmd->add_option("--diff", options->diff,
                  "Write a heat map of the differences (white: at or over --fail; magenta: NaN in one image)");
  cmd->add_flag("--json", options->json, "Print the report as JSON");
  cmd->callback([options, &action] { action = [options] { return run_compare(*options); }; });
}

}  // namespace rtpro::cli
