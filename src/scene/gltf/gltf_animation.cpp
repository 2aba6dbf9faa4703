#include "gltf_animation.h"

#include "gltf_accessor.h"
#include "gltf_morph.h"
#include "gltf_quaternion.h"
#include "rtpro/core/error.h"
#include "ascii_scan.h"
#include "rtpro/core/printable_text.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

namespace rtpro::gltf {

namespace {

std::string animation_path(std::size_t animation) { return "animations[" + std::to_string(animation) + "]"; }

Interpolation interpolation_of(const std::string& name, const AccessorReader& reader, const std::string& path) {
  if (name == "LINEAR" || name.empty()) return Interpolation::kLinear;
  if (name == "STEP") return Interpolation::kStep;
  if (name == "CUBICSPLINE") return Interpolation::kCubicSpline;
  reader.fail(path, "unknown interpolation " + ascii::quoted(name) + " (LINEAR, STEP or CUBICSPLINE)");
}

// Reads one sampler's keys; its width comes from the channels that use it (every one of them
// must agree, which the caller checks).
AnimationSampler read_sampler(const tinygltf::AnimationSampler& s, const AccessorReader& reader,
                              const std::string& path, AnimatedPath target, std::size_t width) {
  AnimationSampler out;
  out.interpolation = interpolation_of(s.interpolation, reader, path + ".interpolation");
  out.width = width;
  out.times = reader.values(s.input, path + ".input", TINYGLTF_TYPE_SCALAR, false);
  if (out.times.empty()) reader.fail(path + ".input", "has no keys");
  for (std::size_t k = 1; k < out.times.size(); ++k)
    if (!(out.times[k] > out.times[k - 1]))
      reader.fail(path + ".input", "key times must increase strictly: key " + std::to_string(k) + " (" +
                                       std::to_string(out.times[k]) + " s) does not come after key " +
                                       std::to_string(k - 1) + " (" + std::to_string(out.times[k - 1]) + " s)");
  const int type = target == AnimatedPath::kRotation  ? TINYGLTF_TYPE_VEC4
                   : target == AnimatedPath::kWeights ? TINYGLTF_TYPE_SCALAR
                                                      : TINYGLTF_TYPE_VEC3;
  const bool integers = target == AnimatedPath::kRotation || target == AnimatedPath::kWeights;
  out.values = reader.values(s.output, path + ".output", type, integers);
  const std::size_t per_key = width * (out.interpolation == Interpolation::kCubicSpline ? 3 : 1);
  if (out.values.size() != out.times.size() * per_key)
    reader.fail(path + ".output",
                std::to_string(out.values.size()) + " numbers for " + std::to_string(out.times.size()) + " keys; " +
                    (out.interpolation == Interpolation::kCubicSpline ? "CUBICSPLINE keys need 3 values of " : "") +
                    std::to_string(width) + " numbers each" +
                    (target == AnimatedPath::kWeights ? " (one per morph target)" : ""));
  if (target == AnimatedPath::kRotation)
    for (std::size_t v = 0; v < out.values.size(); v += 4)
      if (out.interpolation != Interpolation::kCubicSpline || (v / 4) % 3 == 1)
        if (!(std::fabs(out.values[v]) + std::fabs(out.values[v + 1]) + std::fabs(out.values[v + 2]) +
                  std::fabs(out.values[v + 3]) >
              0.0f))
          reader.fail(path + ".output", "key " + std::to_string(v / per_key) + " is a zero quaternion");
  return out;
}

std::size_t width_of(AnimatedPath path, std::size_t targets) {
  switch (path) {
    case AnimatedPath::kTranslation:
    case AnimatedPath::kScale: return 3;
    case AnimatedPath::kRotation: return 4;
    case AnimatedPath::kWeights: return targets;
  }
  return 0;
}

bool path_of(const std::string& name, AnimatedPath& path) {
  if (name == "translation") path = AnimatedPath::kTranslation;
  else if (name == "rotation") path = AnimatedPath::kRotation;
  else if (name == "scale") path = AnimatedPath::kScale;
  else if (name == "weights") path = AnimatedPath::kWeights;
  else return false;
  return true;
}

Animation read_animation(const tinygltf::Model& model, std::size_t index, const AccessorReader& reader,
                         std::vector<std::string>& warnings) {
  const tinygltf::Animation& a = model.animations[index];
  const std::string path = animation_path(index);
  Animation out;
  out.name = a.name;
  // What each sampler animates, from the first channel that uses it; -1: none yet.
  std::vector<int> width_of_sampler(a.samplers.size(), -1);
  std::vector<AnimatedPath> path_of_sampler(a.samplers.size(), AnimatedPath::kTranslation);
  for (std::size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& channel = a.channels[c];
    const std::string channel_path = path + ".channels[" + std::to_string(c) + "]";
    AnimatedPath target;
    if (!path_of(channel.target_path, target)) {
      warnings.push_back(reader.file() + ": " + channel_path + ".target.path: " + ascii::quoted(channel.target_path) +
                         " is not animated by rtpro; the channel is skipped");
      continue;
    }
    if (channel.target_node < 0) continue;  // no node: the specification lets extensions target other things
    if (std::size_t(channel.target_node) >= model.nodes.size())
      reader.fail(channel_path + ".target.node", "node " + std::to_string(channel.target_node) + " does not exist");
    const tinygltf::Node& node = model.nodes[std::size_t(channel.target_node)];
    if (!node.matrix.empty())
      reader.fail(channel_path + ".target.node", "nodes[" + std::to_string(channel.target_node) +
                                                     "] has a matrix; the specification lets animations target "
                                                     "only nodes placed by translation, rotation and scale");
    std::size_t targets = 0;
    if (target == AnimatedPath::kWeights) {
      targets = node.mesh >= 0 && std::size_t(node.mesh) < model.meshes.size()
                    ? morph_target_count(model, node.mesh, reader)
                    : 0;
      if (targets == 0)
        reader.fail(channel_path + ".target.path",
                    "weights, but nodes[" + std::to_string(channel.target_node) + "] draws no mesh with morph targets");
    }
    if (channel.sampler < 0 || std::size_t(channel.sampler) >= a.samplers.size())
      reader.fail(channel_path + ".sampler", "sampler " + std::to_string(channel.sampler) + " does not exist");
    const auto s = std::size_t(channel.sampler);
    const int width = int(width_of(target, targets));
    if (width_of_sampler[s] >= 0 && (width_of_sampler[s] != width || path_of_sampler[s] != target))
      reader.fail(channel_path + ".sampler",
                  "sampler " + std::to_string(s) + " already animates another kind of value for another channel");
    width_of_sampler[s] = width;
    path_of_sampler[s] = target;
    out.channels.push_back({std::uint32_t(channel.target_node), target, std::uint32_t(s)});
  }
  for (std::size_t s = 0; s < a.samplers.size(); ++s) {
    const std::string sampler_path = path + ".samplers[" + std::to_string(s) + "]";
    // A sampler no channel uses is never sampled, and what it would animate is unknown: not read.
    if (width_of_sampler[s] < 0) {
      out.samplers.emplace_back();
      continue;
    }
    // An accessor's error (accessors[4]: element 2 is not a finite number) names the sampler too.
    try {
      out.samplers.push_back(
          read_sampler(a.samplers[s], reader, sampler_path, path_of_sampler[s], std::size_t(width_of_sampler[s])));
    } catch (const InputError& e) {
      if (e.message().rfind(sampler_path, 0) == 0) throw;
      throw InputError(e.where(), sampler_path + ": " + e.message());
    }
  }
  return out;
}

// The value part of key k (CUBICSPLINE keys hold in-tangent, value, out-tangent).
const float* key_value(const AnimationSampler& s, std::size_t k) {
  const std::size_t w = s.width;
  return s.interpolation == Interpolation::kCubicSpline ? &s.values[(3 * k + 1) * w] : &s.values[k * w];
}

void normalize_rotation(std::span<double> q) {
  const Quaternion unit = normalized({q[0], q[1], q[2], q[3]});
  q[0] = unit.x, q[1] = unit.y, q[2] = unit.z, q[3] = unit.w;
}

}  // namespace

std::vector<Animation> read_animations(const tinygltf::Model& model, const AccessorReader& reader,
                                       std::vector<std::string>& warnings) {
  std::vector<Animation> animations;
  for (std::size_t a = 0; a < model.animations.size(); ++a)
    animations.push_back(read_animation(model, a, reader, warnings));
  return animations;
}

void sample(const AnimationSampler& s, double seconds, bool rotation, std::span<double> out) {
  const std::size_t w = s.width, keys = s.times.size();
  const auto copy = [&](const float* value) {
    for (std::size_t i = 0; i < w; ++i) out[i] = value[i];
    if (rotation) normalize_rotation(out);
  };
  // Before the first key, after the last, and NaN: the nearest end's value.
  if (!(seconds > double(s.times.front()))) return copy(key_value(s, 0));
  if (!(seconds < double(s.times.back()))) return copy(key_value(s, keys - 1));
  const std::size_t k = std::size_t(std::upper_bound(s.times.begin(), s.times.end(), seconds) - s.times.begin()) - 1;
  if (s.interpolation == Interpolation::kStep) return copy(key_value(s, k));
  const double t0 = s.times[k], t1 = s.times[k + 1], interval = t1 - t0;
  const double u = (seconds - t0) / interval;
  const float* a = key_value(s, k);
  const float* b = key_value(s, k + 1);
  if (s.interpolation == Interpolation::kLinear) {
    if (rotation) {
      const Quaternion q = slerp({a[0], a[1], a[2], a[3]}, {b[0], b[1], b[2], b[3]}, u);
      out[0] = q.x, out[1] = q.y, out[2] = q.z, out[3] = q.w;
      return;
    }
    for (std::size_t i = 0; i < w; ++i) out[i] = (1.0 - u) * a[i] + u * b[i];
    return;
  }
  // CUBICSPLINE: the Hermite basis, tangents scaled by the interval (glTF 2.0, Appendix C).
  const float* out_tangent = a + w;  // b_k, after v_k
  const float* in_tangent = b - w;   // a_{k+1}, before v_{k+1}
  const double u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  for (std::size_t i = 0; i < w; ++i)
    out[i] = h00 * a[i] + h10 * interval * out_tangent[i] + h01 * b[i] + h11 * interval * in_tangent[i];
  if (rotation) normalize_rotation(out);
}

double animation_end(const std::vector<Animation>& animations) {
  double end = 0.0;
  for (const Animation& a : animations)
    for (const AnimationChannel& c : a.channels) end = std::max(end, double(a.samplers[c.sampler].times.back()));
  return end;
}

}  // namespace rtpro::gltf
