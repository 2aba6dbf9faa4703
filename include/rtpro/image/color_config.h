#pragma once
// The OpenColorIO config rtpro encodes images with, and the display/view transforms taken from it.
// Which config: the --ocio-config file if given, else the file named by $OCIO, else the config
// bundled into the binary (src/image/rtpro_config.ocio). OpenColorIO stays out of this header so
// callers that only want to print the source don't pull it in.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtpro {

// Encodes scene-linear RGB (the config's scene_linear role) for one display and view.
// Does not clamp: the sRGB curve passes values above 1 through.
class DisplayTransform {
 public:
  const std::string& display() const { return display_; }
  const std::string& view() const { return view_; }
  // Transforms `pixel_count` interleaved RGB triples in place.
  void apply(float* rgb, std::size_t pixel_count) const;

 private:
  friend class ColorConfig;
  struct Processor;
  DisplayTransform(std::string display, std::string view, std::shared_ptr<const Processor> processor);

  std::string display_;
  std::string view_;
  std::shared_ptr<const Processor> processor_;
};

class ColorConfig {
 public:
  // Applies the precedence above. Throws InputError naming the file when it cannot be read or is
  // not a valid config.
  static ColorConfig load(const std::optional<std::filesystem::path>& command_line_config);
  static ColorConfig bundled();

  // Where the config came from: "bundled", "$OCIO=/path" or "--ocio-config /path".
  const std::string& source() const { return source_; }

  std::vector<std::string> displays() const;
  std::vector<std::string> views(const std::string& display) const;
  std::string default_display() const;
  std::string default_view(const std::string& display) const;

  // Empty names pick the config's default display and that display's default view. Throws
  // InputError listing the available displays (or views) for an unknown name.
  DisplayTransform display_transform(const std::string& display, const std::string& view) const;

  // From the named colour space (e.g. "sRGB - Texture") to scene_linear: textures are decoded
  // with it before shading. The result is a DisplayTransform only in type (an RGB processor;
  // display() is empty, view() the colour space). Throws InputError for an unknown name.
  DisplayTransform to_scene_linear(const std::string& colorspace) const;

 private:
  struct Config;
  ColorConfig(std::shared_ptr<const Config> config, std::string source);

  std::shared_ptr<const Config> config_;
  std::string source_;
};

}  // namespace rtpro
