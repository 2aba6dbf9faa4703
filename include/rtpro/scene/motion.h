#pragma once
// Motion during a frame's exposure, as the scene description and the render scene store it.
//
// The camera's shutter (`camera.shutter: [open, close]`) is in frames relative to the frame being
// rendered: [-0.25, 0.25] exposes a half frame centred on it (Cycles' "shutter 0.5, centre"), [0, 0]
// (the default) exposes an instant and nothing blurs.
//
// Whatever moves during the shutter stores TIME STEPS: values taken at times spaced uniformly over
// [open, close], the first at open and the last at close (motion_step_times gives the times of a
// frame; a scene reader evaluates its animation there). An empty list of steps means static; a
// non-empty one has 2 to kMaxMotionSteps entries. Between neighbouring steps the value is
// interpolated LINEARLY, the same formula on both backends and as Embree's time steps
// (motion_segment + lerp below): an instance's 3×4 matrix entry by entry, a mesh's vertices, a
// sphere's centre. A rotation therefore follows the chord between steps, not the arc: a reader
// takes enough steps for the arc, which sample_transform_motion does for any transform it can
// evaluate at a time (YAML keyframes, glTF TRS channels): it doubles the segments until every
// segment's midpoint lies within kMotionChordTolerance of the true transform there.
//
// A reader of animation (glTF, YAML keyframes) calls motion_step_times(scene.camera.shutter,
// frame, n) for the times (in frames; seconds = frames / render.fps) to evaluate n steps at, or
// sample_transform_motion for a transform; `frame` is the frame being rendered (--frames, the
// scene variable `frame`).
//
// A ray's time is a float in [0, 1] over the shutter (0 at open, 1 at close): the renderer picks
// it per camera sample and every ray of the path keeps it.
//
// Where motion lives:
//  - InstanceDesc::transform_steps (scene/description.h) and Instance::object_to_world_steps
//    (scene/render_scene.h): object to parent (to world) per step; `transform` stays the value at
//    the frame's time, for whatever ignores motion (bounds reports, light placement).
//  - SphereDesc::center_steps: the centre per step; `center` stays the value at the frame's time.
//  - TriangleMesh::vertex_steps (scene/mesh.h): every vertex's position per step (each step as
//    long as `vertices`, which stays the frame's positions); normal_steps likewise, or empty when
//    the shading normals do not move (or the mesh has none).
#include "rtpro/core/transform.h"
#include "rtpro/core/vec3.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rtpro {

struct Shutter {
  float open = 0.0f;   // frames relative to the frame's time
  float close = 0.0f;  // >= open
  // How the shutter exposes (RenderMan's shutterOpening), as fractions of [open, close]: it opens
  // linearly until `opening`, exposes fully until `closing` and closes linearly to the end. [0, 1]
  // is a box, every instant exposed alike; [0.5, 0.5] a triangle.
  float opening = 0.0f;
  float closing = 1.0f;  // opening <= closing, both in [0, 1]
  // Whether anything can blur: an instant shutter renders exactly as before motion existed.
  bool is_open() const { return close > open; }
  bool is_box() const { return opening == 0.0f && closing == 1.0f; }
  bool operator==(const Shutter&) const = default;
};

// A camera sample's time in [0, 1] over the shutter from a uniform sample `u` in [0, 1), taken as
// often as the shutter exposes it: `u` itself for a box; otherwise the inverse of the trapezoid's
// cumulative exposure (ramp areas t²/2a and (1 − t)²/2(1 − b), the plateau between).
inline float shutter_time(const Shutter& shutter, float u) {
  if (shutter.is_box()) return u;
  const double a = shutter.opening, b = shutter.closing;
  const double exposure = 0.5 * (1.0 + b - a);
  const double y = static_cast<double>(u) * exposure;
  double t;
  if (y < 0.5 * a) t = std::sqrt(2.0 * a * y);
  else if (y <= exposure - 0.5 * (1.0 - b)) t = y + 0.5 * a;
  else t = 1.0 - std::sqrt(std::max(0.0, 2.0 * (1.0 - b) * (exposure - y)));
  return std::clamp(static_cast<float>(t), 0.0f, 1.0f);
}

// Embree's limit on a geometry's time steps (RTC_MAX_TIME_STEP_COUNT).
inline constexpr int kMaxMotionSteps = 129;

// The times (in frames) of `step_count` steps over the shutter of frame `frame`: the first at
// frame + open, the last at frame + close. A scene reader evaluates its animation at these. With a
// closed shutter (or step_count 1) the one time is frame + open.
inline std::vector<double> motion_step_times(const Shutter& shutter, double frame, int step_count) {
  const int count = shutter.is_open() ? std::clamp(step_count, 2, kMaxMotionSteps) : 1;
  std::vector<double> times(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double along = count == 1 ? 0.0 : static_cast<double>(i) / (count - 1);
    times[static_cast<std::size_t>(i)] = frame + shutter.open + (shutter.close - shutter.open) * along;
  }
  return times;
}

// Which segment between steps a ray time in [0, 1] falls in, and where in it: Embree's own
// formula (getTimeSegment), so both backends pick the same segment and fraction.
struct MotionSegment {
  std::uint32_t index = 0;  // steps index and index + 1
  float fraction = 0.0f;    // 0 at step `index`, 1 at the next
};
inline MotionSegment motion_segment(float time, std::size_t step_count) {
  const float segments = static_cast<float>(step_count - 1);
  const float scaled = time * segments;
  const float index = std::clamp(std::floor(scaled), 0.0f, segments - 1.0f);
  return {static_cast<std::uint32_t>(index), scaled - index};
}

inline float motion_lerp(float a, float b, float t) { return (1.0f - t) * a + t * b; }
inline Vec3 motion_lerp(const Vec3& a, const Vec3& b, float t) {
  return {motion_lerp(a.x, b.x, t), motion_lerp(a.y, b.y, t), motion_lerp(a.z, b.z, t)};
}
inline Affine motion_lerp(const Affine& a, const Affine& b, float t) {
  Affine result;
  for (std::size_t r = 0; r < 3; ++r)
    for (std::size_t c = 0; c < 4; ++c) result.m[r][c] = motion_lerp(a.m[r][c], b.m[r][c], t);
  return result;
}

// The value of `steps` (non-empty) at ray time `time` in [0, 1].
template <typename T>
T value_at_time(std::span<const T> steps, float time) {
  if (steps.size() == 1) return steps[0];
  const MotionSegment segment = motion_segment(time, steps.size());
  return motion_lerp(steps[segment.index], steps[segment.index + 1], segment.fraction);
}

// How far (relative to the transform's scale, at least 1 scene unit) a segment's linear
// interpolation may stray from the true transform at its midpoint: 1e-3 takes 33 steps for a 90°
// turn, whose chord then deviates from the arc by a thousandth of the radius.
inline constexpr double kMotionChordTolerance = 1e-3;

// The steps of a transform evaluated by `at(time in frames)` over the shutter of frame `frame`:
// empty when it does not change during the shutter (or the shutter is closed), else 2, 3, 5, 9 ...
// up to kMaxMotionSteps steps, as few as keep every segment within kMotionChordTolerance.
template <typename At>
std::vector<Affine> sample_transform_motion(const Shutter& shutter, double frame, At&& at) {
  if (!shutter.is_open()) return {};
  const auto deviation = [](const Affine& a, const Affine& b) {
    double scale = 1.0, worst = 0.0;
    for (std::size_t r = 0; r < 3; ++r)
      for (std::size_t c = 0; c < 4; ++c) {
        if (c < 3) scale = std::max(scale, std::fabs(static_cast<double>(a.m[r][c])));
        worst = std::max(worst, std::fabs(static_cast<double>(a.m[r][c]) - b.m[r][c]));
      }
    return worst / scale;
  };
  for (int count = 2;; count = 2 * count - 1) {
    const std::vector<double> times = motion_step_times(shutter, frame, count);
    std::vector<Affine> steps;
    for (double time : times) steps.push_back(at(time));
    bool close_enough = true;
    for (int i = 0; i + 1 < count && close_enough; ++i)
      close_enough = deviation(at(0.5 * (times[i] + times[i + 1])), motion_lerp(steps[i], steps[i + 1], 0.5f)) <=
                     kMotionChordTolerance;
    if (close_enough || 2 * count - 1 > kMaxMotionSteps) {
      if (std::all_of(steps.begin(), steps.end(), [&](const Affine& s) { return s == steps.front(); })) return {};
      return steps;
    }
  }
}

// `steps` resampled to `count` uniformly spaced steps (for composing motions of different step
// counts, e.g. an animated instance inside an animated instance).
template <typename T>
std::vector<T> resample_steps(std::span<const T> steps, int count) {
  std::vector<T> result;
  for (int i = 0; i < count; ++i)
    result.push_back(value_at_time(steps, count == 1 ? 0.0f : static_cast<float>(i) / static_cast<float>(count - 1)));
  return result;
}

// a ∘ b over the shutter, each given by its value at the frame's time and its steps (empty:
// static): the steps of the composition (empty when neither moves), at the larger step count.
inline std::vector<Affine> compose_steps(const Affine& a, std::span<const Affine> a_steps, const Affine& b,
                                         std::span<const Affine> b_steps) {
  if (a_steps.empty() && b_steps.empty()) return {};
  const int count = static_cast<int>(std::max(a_steps.size(), b_steps.size()));
  const std::vector<Affine> a_all = a_steps.empty() ? std::vector<Affine>(count, a) : resample_steps(a_steps, count);
  const std::vector<Affine> b_all = b_steps.empty() ? std::vector<Affine>(count, b) : resample_steps(b_steps, count);
  std::vector<Affine> steps;
  for (int i = 0; i < count; ++i) steps.push_back(compose(a_all[i], b_all[i]));
  return steps;
}

}  // namespace rtpro
