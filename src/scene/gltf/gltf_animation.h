#pragma once
// glTF animations: channels that key a node's translation, rotation, scale or morph weights, each
// through a sampler of key times (seconds) and values.
// - Interpolations as the specification gives them: STEP (the key at or before the time), LINEAR
//   (rotations along the shorter arc by slerp, normalised) and CUBICSPLINE (Hermite segments whose
//   tangents, stored per key as in-tangent, value, out-tangent, are scaled by the key interval;
//   rotations normalised). Before the first key the first value holds, after the last the last.
// - Read with every bound checked (gltf_accessor.h): input times finite and strictly increasing,
//   outputs of the type and count the path and interpolation need (weights: one per morph target
//   of the node's mesh), targets that exist and carry no `matrix`. A channel of an unknown path
//   (an extension's) is skipped with a warning. Errors name the JSON path
//   (`animations[0].samplers[1].input`).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace rtpro::gltf {

class AccessorReader;

enum class Interpolation : std::uint8_t { kStep, kLinear, kCubicSpline };
enum class AnimatedPath : std::uint8_t { kTranslation, kRotation, kScale, kWeights };

struct AnimationSampler {
  Interpolation interpolation = Interpolation::kLinear;
  std::vector<float> times;   // seconds, strictly increasing, at least one
  std::vector<float> values;  // per key `width` numbers, or three groups of them for CUBICSPLINE
  std::size_t width = 0;      // 3 (translation, scale), 4 (rotation x, y, z, w) or the target count
};

struct AnimationChannel {
  std::uint32_t node;
  AnimatedPath path;
  std::uint32_t sampler;
};

struct Animation {
  std::string name;
  std::vector<AnimationSampler> samplers;
  std::vector<AnimationChannel> channels;
};

// The file's animations, validated.
std::vector<Animation> read_animations(const tinygltf::Model& model, const AccessorReader& reader,
                                       std::vector<std::string>& warnings);

// The sampler's value at `seconds` into out (sampler.width numbers); `rotation` makes it a unit
// quaternion interpolated on the sphere.
void sample(const AnimationSampler& sampler, double seconds, bool rotation, std::span<double> out);

// The time of the last key of any animation (0 for none): how long the animation runs.
double animation_end(const std::vector<Animation>& animations);

}  // namespace rtpro::gltf
