#include "rtpro/image/color_config.h"

#include "rtpro/core/error.h"

#include <OpenColorIO/OpenColorIO.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace rtpro {

extern const char* const kBundledOcioConfig;

struct ColorConfig::Config {
  OCIO::ConstConfigRcPtr ocio;
};

struct DisplayTransform::Processor {
  OCIO::ConstCPUProcessorRcPtr cpu;
};

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "\"" : ", \"") + name + "\"";
  return text;
}

OCIO::ConstConfigRcPtr validated(OCIO::ConstConfigRcPtr config) {
  config->validate();
  return config;
}

OCIO::ConstConfigRcPtr read_config_file(const std::filesystem::path& file, const std::string& chosen_by) {
  // OpenColorIO's own message for a missing file does not say which option pointed at it.
  if (!std::ifstream(file).good())
    throw InputError(SourceLocation{file.string()}, "cannot read the OpenColorIO config (chosen by " + chosen_by + ")");
  try {
    return validated(OCIO::Config::CreateFromFile(file.c_str()));
  } catch (const OCIO::Exception& e) {
    throw InputError(SourceLocation{file.string()},
                     "invalid OpenColorIO config (chosen by " + chosen_by + "): " + e.what());
  }
}

}  // namespace

ColorConfig::ColorConfig(std::shared_ptr<const Config> config, std::string source)
    : config_(std::move(config)), source_(std::move(source)) {}

ColorConfig ColorConfig::bundled() {
  // Parsed once: the text is compiled in and cannot change while rtpro runs.
  static const auto config = [] {
    std::istringstream text(kBundledOcioConfig);
    return std::make_shared<const Config>(Config{validated(OCIO::Config::CreateFromStream(text))});
  }();
  return ColorConfig(config, "bundled");
}

ColorConfig ColorConfig::load(const std::optional<std::filesystem::path>& command_line_config) {
  if (command_line_config) {
    const auto& file = *command_line_config;
    return ColorConfig(std::make_shared<const Config>(Config{read_config_file(file, "--ocio-config")}),
                       "--ocio-config " + file.string());
  }
  const char* environment = std::getenv("OCIO");
  if (environment && *environment) {
    const std::filesystem::path file = environment;
    return ColorConfig(std::make_shared<const Config>(Config{read_config_file(file, "$OCIO")}),
                       "$OCIO=" + file.string());
  }
  return bundled();
}

std::vector<std::string> ColorConfig::displays() const {
  std::vector<std::string> names;
  for (int i = 0; i < config_->ocio->getNumDisplays(); ++i) names.emplace_back(config_->ocio->getDisplay(i));
  return names;
}

std::vector<std::string> ColorConfig::views(const std::string& display) const {
  std::vector<std::string> names;
  for (int i = 0; i < config_->ocio->getNumViews(display.c_str()); ++i)
    names.emplace_back(config_->ocio->getView(display.c_str(), i));
  return names;
}

std::string ColorConfig::default_display() const { return config_->ocio->getDefaultDisplay(); }

std::string ColorConfig::default_view(const std::string& display) const {
  return config_->ocio->getDefaultView(display.c_str());
}

namespace {

// Names in these messages come from scene files and the command line (a texture's colorspace, a
// --display): control characters are shown as \xNN, never sent to the terminal raw.
std::string without_control_characters(const std::string& text) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7f) {
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

DisplayTransform ColorConfig::display_transform(const std::string& display, const std::string& view) const {
  const std::string chosen_display = display.empty() ? default_display() : display;
  const auto known_displays = displays();
  if (std::find(known_displays.begin(), known_displays.end(), chosen_display) == known_displays.end())
    throw InputError(without_control_characters("unknown display \"" + chosen_display + "\" in the " + source_ +
                                                " OpenColorIO config; available: " + join(known_displays)));
  const std::string chosen_view = view.empty() ? default_view(chosen_display) : view;
  const auto known_views = views(chosen_display);
  if (std::find(known_views.begin(), known_views.end(), chosen_view) == known_views.end())
    throw InputError(without_control_characters("unknown view \"" + chosen_view + "\" for display \"" + chosen_display +
                                                "\" in the " + source_ +
                                                " OpenColorIO config; available: " + join(known_views)));
  try {
    const auto processor = config_->ocio->getProcessor(OCIO::ROLE_SCENE_LINEAR, chosen_display.c_str(),
                                                       chosen_view.c_str(), OCIO::TRANSFORM_DIR_FORWARD);
    return DisplayTransform(chosen_display, chosen_view,
                            std::make_shared<const DisplayTransform::Processor>(
                                DisplayTransform::Processor{processor->getDefaultCPUProcessor()}));
  } catch (const OCIO::Exception& e) {
    throw InputError(without_control_characters("the " + source_ +
                                                " OpenColorIO config cannot encode scene_linear for display \"" +
                                                chosen_display + "\", view \"" + chosen_view + "\": " + e.what()));
  }
}

DisplayTransform ColorConfig::to_scene_linear(const std::string& colorspace) const {
  try {
    const auto processor = config_->ocio->getProcessor(colorspace.c_str(), OCIO::ROLE_SCENE_LINEAR);
    return DisplayTransform("", colorspace,
                            std::make_shared<const DisplayTransform::Processor>(
                                DisplayTransform::Processor{processor->getDefaultCPUProcessor()}));
  } catch (const OCIO::Exception& e) {
    throw InputError(without_control_characters("the " + source_ + " OpenColorIO config cannot convert \"" +
                                                colorspace + "\" to scene_linear: " + e.what()));
  }
}

DisplayTransform::DisplayTransform(std::string display, std::string view, std::shared_ptr<const Processor> processor)
    : display_(std::move(display)), view_(std::move(view)), processor_(std::move(processor)) {}

void DisplayTransform::apply(float* rgb, std::size_t pixel_count) const {
  // OpenColorIO converts whatever it is given into scratch RGBA float buffers first: a 1024×1024
  // image in one call cost 50 MB of peak memory. Bounded chunks keep that to a few hundred KB a
  // thread. A CPU processor is immutable and its apply thread-safe, so the chunks go side by side
  // (each pixel's transform is its own: the result is the same): one thread took 20 ms of a
  // 1024² PNG's write in the sRGB transfer's powf.
  constexpr std::size_t kChunkPixels = 16384;
  const std::size_t chunks = (pixel_count + kChunkPixels - 1) / kChunkPixels;
  tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t chunk) {
    const std::size_t first = chunk * kChunkPixels;
    const std::size_t count = std::min(kChunkPixels, pixel_count - first);
    OCIO::PackedImageDesc pixels(rgb + 3 * first, static_cast<long>(count), 1, 3);
    processor_->cpu->apply(pixels);
  });
}

}  // namespace rtpro
