#include "rtpro/image/texture_lookup.h"

#include "rtpro/core/error.h"
#include "rtpro/core/temporary_folder.h"
#include "rtpro/image/color_config.h"
#include "rtpro/image/image_io.h"
#include "image_read_budget.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/texture.h>

#include <fstream>
#include <string>
#include <vector>

namespace rtpro {

namespace {

constexpr const char* kTextureFolderPrefix = "rtpro-textures-";

// The file's pixels as linear RGB floats: grey and grey-alpha images repeat their first channel,
// extra channels (alpha) are dropped, then the colour space is converted to scene_linear.
std::vector<float> linear_rgb(const Image& image, const DisplayTransform& to_linear) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  const std::size_t channels = image.channels.size();
  std::vector<float> rgb(pixels * 3);
  for (std::size_t p = 0; p < pixels; ++p)
    for (std::size_t c = 0; c < 3; ++c) rgb[3 * p + c] = image.data[p * channels + (channels >= 3 ? c : 0)];
  to_linear.apply(rgb.data(), pixels);
  return rgb;
}

OIIO::TextureOpt::Wrap oiio_wrap(TextureWrap wrap) {
  switch (wrap) {
    case TextureWrap::kRepeat: return OIIO::TextureOpt::WrapPeriodic;
    case TextureWrap::kClamp: return OIIO::TextureOpt::WrapClamp;
    case TextureWrap::kMirror: return OIIO::TextureOpt::WrapMirror;
    case TextureWrap::kBlack: return OIIO::TextureOpt::WrapBlack;
  }
  return OIIO::TextureOpt::WrapPeriodic;
}

// One texture system for the process, never destroyed: OpenImageIO 2.4.7's TextureSystem::destroy
// deletes the implementation through the base class with a sized delete of the wrong size
// (AddressSanitizer: new-delete-type-mismatch, 184 against 1 bytes). Lookups invalidate their
// own files when they end.
OIIO::TextureSystem& texture_system() {
  static OIIO::TextureSystem* const system = [] {
    OIIO::TextureSystem* created = OIIO::TextureSystem::create(/*shared=*/false);
    created->attribute("max_open_files", 100);
    created->attribute("autotile", 0);
    return created;
  }();
  return *system;
}

// What preparing a texture keeps per pixel beside its decoded floats: the linear RGB copy (12
// bytes), the float mip chain make_texture builds (4/3 of that: 16) and its working copy of the
// source (12). A 0.8 MB PNG declaring 16384x16384 pixels took 7.2 GB and a minute before this
// was counted against the budget from the header.
constexpr std::uint64_t kTexturePreparationBytesPerPixel = 12 + 16 + 12;

class OiioTextureLookup final : public TextureLookup {
 public:
  OiioTextureLookup(std::span<const TextureSource> sources, std::uint64_t max_bytes) : system_(&texture_system()) {
    const ColorConfig config = ColorConfig::bundled();
    for (std::size_t i = 0; i < sources.size(); ++i) {
      try {
        prepare(sources[i], i, config, max_bytes);
      } catch (const InputError& error) {
        // The image's own file says what is wrong with it; where the scene named it says which
        // material to change (one image may be behind many).
        if (sources[i].named_at.empty()) throw;
        throw InputError(error.where(), error.message() + " (the texture named at " + sources[i].named_at + ")");
      }
    }
  }

  // Decodes the texture to linear floats and writes it as the private .tx file the system reads.
  void prepare(const TextureSource& source, std::size_t i, const ColorConfig& config, std::uint64_t max_bytes) {
    const Image image =
        read_image_counting(source.bytes ? write_embedded(source, i) : source.file, max_bytes,
                            kTexturePreparationBytesPerPixel, "with its linear and mip-mapped texture copies");
    const std::vector<float> rgb = linear_rgb(image, config.to_scene_linear(source.colorspace));
    const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
    const OIIO::ImageBuf linear(spec, const_cast<float*>(rgb.data()));
    const std::filesystem::path tx = folder_.path() / (std::to_string(i) + ".tx");
    OIIO::ImageSpec config_spec;
    config_spec.attribute("maketx:filtername", "box");
    // A private copy, read once: zip-compressing its mip levels cost 20 ms of a textured
    // render's serial start.
    config_spec.attribute("compression", "none");
    if (!OIIO::ImageBufAlgo::make_texture(OIIO::ImageBufAlgo::MakeTxTexture, linear, tx.string(), config_spec))
      throw InputError(source.file.string() + ": cannot prepare the texture: " + OIIO::geterror());
    files_.emplace_back(tx.string());
    OIIO::TextureSystem::TextureHandle* handle = system_->get_texture_handle(files_.back());
    if (!handle) throw InputError(source.file.string() + ": the texture system cannot open its decoded copy");
    handles_.push_back(handle);
  }

  // An image stored inside a glTF, as a file in the private folder (for rtpro's checked reader).
  std::filesystem::path write_embedded(const TextureSource& source, std::size_t index) const {
    const std::filesystem::path file =
        folder_.path() / ("embedded" + std::to_string(index) + source.file.extension().string());
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(source.bytes->data()), static_cast<std::streamsize>(source.bytes->size()));
    if (!out.flush()) throw RuntimeError("cannot write a decoded texture into " + folder_.path().string());
    return file;
  }

  Color lookup(std::uint32_t index, float s, float t, const TextureSampling& sampling) const override {
    OIIO::TextureOpt options;
    options.swrap = oiio_wrap(sampling.wrap_s);
    options.twrap = oiio_wrap(sampling.wrap_t);
    // Bilinear: OpenImageIO's default (smart bicubic) smooths even at a texel's centre when there
    // is no footprint to filter over; camera rays carry none, and supersampling does the rest.
    options.interpmode =
        sampling.filter == TextureFilter::kNearest ? OIIO::TextureOpt::InterpClosest : OIIO::TextureOpt::InterpBilinear;
    float rgb[3] = {0.0f, 0.0f, 0.0f};
    system_->texture(handles_[index], system_->get_perthread_info(), options, s, t, 0.0f, 0.0f, 0.0f, 0.0f, 3, rgb);
    return {rgb[0], rgb[1], rgb[2]};
  }

 private:
  // Declared first so it is removed last, after the files are forgotten by the system.
  TemporaryFolder folder_{kTextureFolderPrefix, "decoded textures"};
  // Forgets this lookup's files (closing them) before the folder holding them goes.
  struct Forget {
    OIIO::TextureSystem* system;
    std::vector<OIIO::ustring>* files;
    ~Forget() {
      for (const OIIO::ustring& file : *files) system->invalidate(file, true);
    }
  };
  OIIO::TextureSystem* system_;
  std::vector<OIIO::ustring> files_;
  Forget forget_{system_, &files_};
  std::vector<OIIO::TextureSystem::TextureHandle*> handles_;
};

}  // namespace

std::unique_ptr<TextureLookup> open_textures(std::span<const TextureSource> sources, std::uint64_t max_bytes) {
  return std::make_unique<OiioTextureLookup>(sources, max_bytes);
}

}  // namespace rtpro
