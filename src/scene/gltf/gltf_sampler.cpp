#include "gltf_sampler.h"

#include "rtpro/core/error.h"

#include <string>

namespace rtpro::gltf {

namespace {

// The WebGL enumerants glTF's samplers use.
constexpr int kNearest = 9728, kLinear = 9729;
constexpr int kNearestMipmapNearest = 9984, kLinearMipmapLinear = 9987;
constexpr int kClampToEdge = 33071, kMirroredRepeat = 33648, kRepeat = 10497;
constexpr int kUnset = -1;  // tinygltf's value for an absent filter

[[noreturn]] void fail(const std::string& file, const std::string& path, int value, const char* allowed) {
  throw InputError(SourceLocation{file}, path + ": " + std::to_string(value) + " is not one of " + allowed);
}

TextureWrap wrap_of(int value, const std::string& file, const std::string& path) {
  switch (value) {
    case kClampToEdge: return TextureWrap::kClamp;
    case kMirroredRepeat: return TextureWrap::kMirror;
    case kRepeat: return TextureWrap::kRepeat;
    default: fail(file, path, value, "33071 (CLAMP_TO_EDGE), 33648 (MIRRORED_REPEAT), 10497 (REPEAT)");
  }
}

}  // namespace

TextureSampling texture_sampling(const tinygltf::Model& model, int texture, const std::string& file) {
  if (texture < 0 || std::size_t(texture) >= model.textures.size()) return {};
  const int index = model.textures[std::size_t(texture)].sampler;
  if (index < 0) return {};
  if (std::size_t(index) >= model.samplers.size())
    throw InputError(SourceLocation{file}, "textures[" + std::to_string(texture) + "].sampler: sampler " +
                                               std::to_string(index) + " does not exist");
  const tinygltf::Sampler& sampler = model.samplers[std::size_t(index)];
  const std::string path = "samplers[" + std::to_string(index) + "]";
  TextureSampling sampling;
  sampling.wrap_s = wrap_of(sampler.wrapS, file, path + ".wrapS");
  sampling.wrap_t = wrap_of(sampler.wrapT, file, path + ".wrapT");
  if (sampler.magFilter == kNearest) sampling.filter = TextureFilter::kNearest;
  else if (sampler.magFilter != kLinear && sampler.magFilter != kUnset)
    fail(file, path + ".magFilter", sampler.magFilter, "9728 (NEAREST), 9729 (LINEAR)");
  const bool known_min = sampler.minFilter == kUnset || sampler.minFilter == kNearest || sampler.minFilter == kLinear ||
                         (sampler.minFilter >= kNearestMipmapNearest && sampler.minFilter <= kLinearMipmapLinear);
  if (!known_min)
    fail(file, path + ".minFilter", sampler.minFilter,
         "9728 (NEAREST), 9729 (LINEAR), 9984-9987 (NEAREST_MIPMAP_NEAREST ... LINEAR_MIPMAP_LINEAR)");
  return sampling;
}

}  // namespace rtpro::gltf
