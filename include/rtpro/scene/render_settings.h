#pragma once
// Settings that change how a scene is rendered rather than what it holds; the scene file's
// `render:` block. Shared by the description and the render scene.
#include "rtpro/core/vec3.h"

#include <cstdint>
#include <optional>

namespace rtpro {

// How light is carried to the camera. `whitted` is the Phong model with mirrors, glass and hard or
// soft shadows (render/integrators/whitted_integrator.h); `path` is physically based unidirectional path tracing with
// multiple importance sampling (render/integrators/path_integrator.h).
enum class Integrator : std::uint8_t { kWhitted, kPath };

// How the path integrator finds light arriving at a non-specular vertex: both strategies,
// weighted by multiple importance sampling (the default), or one of them alone (for tests and
// comparisons: each alone is unbiased, only noisier). Point and directional lights, which BSDF
// samples cannot reach, are always light-sampled.
enum class PathSampling : std::uint8_t { kMis, kLight, kBsdf };

constexpr const char* path_sampling_name(PathSampling sampling) {
  switch (sampling) {
    case PathSampling::kMis: return "mis";
    case PathSampling::kLight: return "light";
    case PathSampling::kBsdf: return "bsdf";
  }
  return "?";
}

// Where a pixel's samples fall in every dimension: `stratified` (render/sampler.h: a jittered grid
// per dimension pair, the Whitted references' sampler) or `sobol` (render/sampling/sobol_sampler.h:
// Owen-scrambled Sobol points, the path integrator's default, lower error at equal spp).
enum class SamplerKind : std::uint8_t { kStratified, kSobol };

constexpr const char* sampler_name(SamplerKind sampler) {
  switch (sampler) {
    case SamplerKind::kStratified: return "stratified";
    case SamplerKind::kSobol: return "sobol";
  }
  return "?";
}

// How the path integrator picks the light it samples at a vertex: `tree` (render/lights/light_tree.h:
// by an estimate of what each light sends to the point) or `power` (by power alone, anywhere).
enum class LightSamplerKind : std::uint8_t { kTree, kPower };

constexpr const char* light_sampler_name(LightSamplerKind kind) {
  switch (kind) {
    case LightSamplerKind::kTree: return "tree";
    case LightSamplerKind::kPower: return "power";
  }
  return "?";
}

// What a light's `color` × `intensity` means, the same under either integrator (scenes/FORMAT.md,
// "Light units"). `whitted` is POV-Ray's reading: a point or spot light does not fall off with
// distance, and a white diffuse surface facing a light shows its colour × intensity (the whitted
// integrator's diffuse term is colour × irradiance, without Lambert's 1/π, so the path integrator
// multiplies every light by π). `radiometric` is pbrt's: W/sr falling off with the square of
// distance for point and spot lights, irradiance for directional lights, radiance for area
// lights (the whitted integrator divides what arrives by π).
enum class LightUnits : std::uint8_t { kWhitted, kRadiometric };

constexpr const char* light_units_name(LightUnits units) {
  switch (units) {
    case LightUnits::kWhitted: return "whitted";
    case LightUnits::kRadiometric: return "radiometric";
  }
  return "?";
}

constexpr const char* integrator_name(Integrator integrator) {
  switch (integrator) {
    case Integrator::kWhitted: return "whitted";
    case Integrator::kPath: return "path";
  }
  return "?";
}

// The path integrator's controls as Cycles has them (its Light Paths panel), each off by default.
struct PathControls {
  // Per-lobe bounce limits: how many of a path's BSDF samples may take a diffuse, glossy
  // (reflection off a microfacet or mirror lobe) or transmission lobe; unset is max_depth, which
  // never binds. The vertex a path reaches when one count reaches its limit adds its emission
  // and ends, as at max_depth.
  std::optional<int> max_diffuse_depth, max_glossy_depth, max_transmission_depth;
  // How many phase function samples (scatterings in a medium) a path may take; unset is max_depth.
  std::optional<int> max_volume_depth;
  // Cycles' Clamp Direct / Indirect: each contribution to a sample whose channel mean is above
  // the limit is scaled down to it (the colour's hue kept); 0 is off. Direct: light reaching the
  // camera after at most one scattering; indirect: the rest.
  float clamp_direct = 0.0f, clamp_indirect = 0.0f;
  // Cycles' Filter Glossy: after a BSDF sample of pdf p (per unit solid angle), later microfacet
  // lobes get GGX α >= 0.5·sqrt(1 − p_min / filter_glossy), p_min the smallest such pdf on the path
  // so far; 0 is off.
  float filter_glossy = 0.0f;
};

struct RenderSettings {
  int spp = 16;       // samples per pixel, 1..65536 (stratified over the most nearly square grid)
  int max_depth = 5;  // bounces after the camera ray: mirror bounces (whitted), path vertices (path)
  PathControls path;  // path integrator only
  Integrator integrator = Integrator::kWhitted;
  PathSampling path_sampling = PathSampling::kMis;
  SamplerKind sampler = SamplerKind::kStratified;  // the scene parser makes `path` default to sobol
  LightSamplerKind light_sampler = LightSamplerKind::kTree;
  // The scene parser always sets it (by default from the integrator the file itself names); left
  // unset, each integrator reads lights in its own units (whitted: LightUnits::kWhitted, path:
  // kRadiometric), as a scene built in code expects.
  std::optional<LightUnits> light_units;
  std::uint64_t seed = 0;
  // Frames per second (`render.fps`): frame f of a glTF animation is its pose at f / fps seconds.
  double fps = 24.0;
  float ambient = 0.2f;
  Color background{0.0f, 0.0f, 0.0f};
};

// The per-lobe bounce limits, each unset one resolved to max_depth.
struct LobeDepths {
  int diffuse, glossy, transmission, volume;
};
inline LobeDepths lobe_depths(const RenderSettings& settings) {
  const int all = settings.max_depth;
  return {settings.path.max_diffuse_depth.value_or(all), settings.path.max_glossy_depth.value_or(all),
          settings.path.max_transmission_depth.value_or(all), settings.path.max_volume_depth.value_or(all)};
}

}  // namespace rtpro
