// `rtpro denoise IN -o OUT`: denoises a rendered image file with rtpro's own denoiser
// (denoise/denoise.h). IN holds R,G,B and, for a good result, the features render writes with
// --aov albedo,normal,depth. OUT gets the denoised colour as R,G,B; an EXR OUT keeps every layer
// of IN and the noisy colour as noisy.R/G/B. Exit codes: 0 written; 2 for an unreadable IN, one without
// the channels the denoiser needs, or bad options; 1 when OUT cannot be written (an existing OUT
// is then left as it was).
#include "command.h"
#include "output_target.h"
#include "render_output.h"
#include "thread_count.h"
#include "rtpro/core/error.h"
#include "rtpro/core/printable_text.h"
#include "memory_option.h"
#include "non_finite_pixels.h"
#include "rtpro/core/memory_budget.h"
#include "rtpro/denoise/denoise.h"
#include "rtpro/image/image_io.h"
#include "rtpro/image/image_size.h"
#include "rtpro/image/output_check.h"

#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

namespace rtpro::cli {

namespace {

struct DenoiseCommandOptions {
  std::string input;
  std::string output;
  std::optional<int> threads;
  DenoiseSettings settings;
  std::string max_memory_mb;  // as typed: see memory_option.h
  bool quiet = false;
};

std::string what_was_used(const DenoiseReport& report) {
  std::string text = "guided by ";
  for (std::size_t i = 0; i < report.features.size(); ++i) text += (i ? ", " : "") + report.features[i];
  if (report.features.empty()) text += "the colour alone";
  text += report.used_measured_noise ? "; noise measured by the renderer" : "; noise estimated from the neighbourhood";
  return text + "; " + std::to_string(report.firefly_pixels) +
         (report.firefly_pixels == 1 ? " firefly" : " fireflies") + " left out";
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1fs", seconds);
  return text;
}

// Refused from the input's header, before a pixel is decoded: a small compressed file can declare
// an image whose denoising needs tens of gigabytes.
void check_denoise_memory(const std::filesystem::path& input, const DenoiseSettings& settings,
                          const MemoryBudget& budget) {
  const ImageSize size = read_image_size(input);
  const std::uint64_t bytes = denoise_peak_bytes(size.width, size.height, size.channels, settings);
  if (bytes <= budget.bytes) return;
  throw InputError(SourceLocation{input.string()},
                   "denoising this " + std::to_string(size.width) + "x" + std::to_string(size.height) + " image of " +
                       std::to_string(size.channels) + " channels would need an estimated " + format_bytes(bytes) +
                       ", more than the memory budget of " + format_bytes(budget.bytes) + " (" + budget.source +
                       "); raise the budget with --max-memory MiB");
}

int run_denoise(const DenoiseCommandOptions& o) {
  const int threads = worker_thread_count(o.threads);
  const std::filesystem::path input = o.input, output = o.output;
  check_image_output(output);  // a typo in -o fails now, not after the denoise
  // Denoising in place would leave no noisy image to denoise again with other settings.
  check_output_is_distinct({"-o", o.output}, {{"the input", o.input}});
  tbb::global_control thread_cap(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));

  const auto start = std::chrono::steady_clock::now();
  const MemoryBudget budget = parse_memory_budget(o.max_memory_mb);
  check_denoise_memory(input, o.settings, budget);
  Image noisy = read_image(input, budget.bytes);
  if (const auto warning = non_finite_pixels_warning(noisy); warning && !o.quiet)
    std::cerr << "rtpro: warning: " << input.string() << ": " << *warning
              << "; the denoiser cannot use them and their neighbours come out wrong\n";
  DenoiseReport report;
  Image denoised;
  try {
    denoised = denoise(noisy, o.settings, &report);
  } catch (const InputError& e) {
    throw InputError(SourceLocation{input.string()}, e.message());
  }
  if (!o.quiet && report.features.size() < 3)
    std::cerr << "rtpro: warning: " << printable_message(input.string())
              << " lacks some of the albedo, N and depth layers (render --aov albedo,normal,depth): the denoiser "
                 "tells less detail from noise without them\n";
  // Only EXR keeps the layers; other formats get the denoised colour alone.
  if (holds_layers(output)) {
    denoised = with_denoised_colour(noisy, denoised);
  }
  noisy = Image();

  ImageWriteOptions write_options;
  write_options.metadata = {{"Software", std::string("rtpro ") + RTPRO_VERSION}, {"rtpro:denoised_from", o.input}};
  write_image(output, denoised, write_options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.quiet)
    std::cerr << "rtpro: wrote " << printable_message(output.string()) << " (" << denoised.width << "x"
              << denoised.height << ", denoised, " << what_was_used(report) << ") in " << seconds_text(seconds) << "\n";
  return kExitOk;
}

}  // namespace

void add_denoise_command(CLI::App& app, Action& action) {
  auto o = std::make_shared<DenoiseCommandOptions>();
  CLI::App* cmd = app.add_subcommand("denoise", "Denoise a rendered image with rtpro's own denoiser");
  cmd->add_option("input", o->input,
                  "Rendered image file (EXR): R,G,B, and for the best result the layers of render --aov "
                  "albedo,normal,depth (and half_a/half_b or variance, when the film writes them)")
      ->required();
  cmd->add_option("-o,--output", o->output,
                  "Output image: the denoised colour as R,G,B; an EXR keeps the input's layers and the noisy colour "
                  "as noisy.R/G/B")
      ->required();
  cmd->add_option("--threads", o->threads, "Worker threads (0: all cores)");
  cmd->add_option("--radius", o->settings.window_radius, "Half-width of the regression window in pixels (1 to 32)")
      ->check(CLI::Range(1, 32))
      ->capture_default_str();
  cmd->add_option("--strength", o->settings.colour_tolerance,
                  "How different (in noise deviations) neighbours' colours may be and still be averaged")
      ->check(CLI::Range(0.01, 100.0))
      ->capture_default_str();
  cmd->add_option("--firefly-threshold", o->settings.firefly_threshold,
                  "Leave out pixels this many times further from their neighbours than noise explains (0: keep all)")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  cmd->add_option("--max-memory", o->max_memory_mb,
                  "Memory budget in MiB, checked against an estimate from the input's header before it is read (0: "
                  "no limit; default: the smaller of 4096 and the available memory)");
  cmd->add_flag("-q,--quiet", o->quiet, "Print only errors");
  cmd->callback([o, &action] { action = [o] { return run_denoise(*o); }; });
}

}  // namespace rtpro::cli
