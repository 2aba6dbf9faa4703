// The executable's side of the image layer (see rtpro/image/image_layer.h): finds and loads
// librtpro_image_oiio.so once, on a background thread or on first use, and forwards the
// OpenImageIO-backed calls of image_io.h, image_size.h, image_compare.h and diff_image.h to it. EXR and PNG
// files are written here without it (direct_output.h), and plain RGB(A) EXR files read (exr_input.h).
#include "rtpro/image/image_layer.h"

#include "direct_output.h"
#include "exr_input.h"
#include "image_header_check.h"
#include "image_layer_api.h"
#include "rtpro/core/error.h"
#include "rtpro/core/plugin_file.h"
#include "rtpro/image/diff_image.h"
#include "rtpro/image/texture_lookup.h"

#include <dlfcn.h>

#include <atomic>
#include <fstream>
#include <future>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace rtpro {

namespace {

// Debian's OpenImageIO pulls in some 260 shared libraries, linked with BIND_NOW: loading the plugin
// binds about 155,000 symbol references at once, each looked up through the loaded objects in
// order, and a library deep in the plugin's breadth-first dependency list walks past a hundred
// others for each of its own symbols (OpenVDB alone binds 57,000). That took 0.2 s of CPU, two
// thirds of it in the dynamic loader's do_lookup_x, on a second core while a render starts (at two
// threads, from the render). Opened one by one, deepest first, each library is near the front of
// its own lookup scope: the same libraries load in about half the CPU time. The build lists them
// beside the plugin (cmake/list_plugin_libraries.cmake); each is opened by soname, through the
// usual search, so the plugin then finds the very objects it would have loaded. One that fails
// alone (a library leaning on symbols of libraries it does not link) is left to the plugin's own
// load, and without the list the plugin simply loads them all itself.
void open_plugin_libraries(const std::filesystem::path& plugin) {
  std::ifstream list(plugin.string() + ".libraries");
  for (std::string soname; std::getline(list, soname);)
    if (!soname.empty() && !dlopen(soname.c_str(), RTLD_LAZY | RTLD_LOCAL)) dlerror();
}

const ImageLayerApi* load_plugin() {
  const std::filesystem::path file = plugin_beside_executable(kImageLayerFileName, "the image layer");
  open_plugin_libraries(file);
  return open_plugin_table<ImageLayerApi>(file, kImageLayerEntryPoint, kImageLayerAbiVersion, RTPRO_VERSION,
                                          "the image layer (OpenImageIO)");
}

struct LoadState {
  std::mutex mutex;
  std::shared_future<const ImageLayerApi*> result;  // valid once a load has started
  std::atomic<bool> in_flight{false};
};

// Never destroyed: a background load may still be running while the process exits.
LoadState& load_state() {
  static LoadState* const state = new LoadState;
  return *state;
}

void load_into(std::promise<const ImageLayerApi*>& promise) {
  try {
    promise.set_value(load_plugin());
  } catch (...) {
    promise.set_exception(std::current_exception());
  }
}

std::shared_future<const ImageLayerApi*> start_load(bool in_background) {
  LoadState& state = load_state();
  const std::lock_guard lock(state.mutex);
  if (state.result.valid()) return state.result;
  auto promise = std::make_shared<std::promise<const ImageLayerApi*>>();
  state.result = promise->get_future().share();
  if (in_background) {
    try {
      state.in_flight = true;
      std::thread([promise, &state] {
        load_into(*promise);
        state.in_flight = false;
      }).detach();
      return state.result;
    } catch (const std::system_error&) {
      state.in_flight = false;  // no thread to spare: load here instead
    }
  }
  load_into(*promise);
  return state.result;
}

const ImageLayerApi& image_layer() { return *start_load(false).get(); }

}  // namespace

void start_loading_image_layer() { start_load(true); }

bool image_layer_loading() { return load_state().in_flight; }

bool writing_needs_image_layer(const std::filesystem::path& file) { return !written_without_openimageio(file); }

bool reading_needs_image_layer(const std::filesystem::path& file) { return !has_exr_signature(file); }

void write_image(const std::filesystem::path& file, const Image& image, const ImageWriteOptions& options) {
  if (!write_without_openimageio(file, image, options)) image_layer().write_image(file, image, options);
}

Image read_image(const std::filesystem::path& file, std::uint64_t max_bytes) {
  if (std::optional<Image> image = read_exr_without_openimageio(file, max_bytes)) return std::move(*image);
  return image_layer().read_image(file, max_bytes);
}

ImageSize read_image_size(const std::filesystem::path& file) {
  if (const std::optional<ImageSize> size = image_size_from_header(file)) return *size;
  return image_layer().read_image_size(file);
}

ImageComparison compare_images(const Image& reference, const Image& test, const CompareThresholds& thresholds) {
  return image_layer().compare_images(reference, test, thresholds);
}

void write_diff_image(const std::filesystem::path& file, const Image& reference, const Image& test, float full_scale) {
  image_layer().write_diff_image(file, reference, test, full_scale);
}

std::unique_ptr<TextureLookup> open_textures(std::span<const TextureSource> sources, std::uint64_t max_bytes) {
  return std::unique_ptr<TextureLookup>(image_layer().open_textures(sources.data(), sources.size(), max_bytes));
}

}  // namespace rtpro
