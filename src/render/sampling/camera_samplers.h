#pragma once
// The render's samplers, both pure functions of (pixel, sample, dimension, seed), and the one its
// settings choose (render.sampler): the single source of every random number a render draws.
#include "rtpro/render/sampler.h"
#include "rtpro/scene/render_settings.h"
#include "sobol_sampler.h"

namespace rtpro {

class CameraSamplers {
 public:
  explicit CameraSamplers(const RenderSettings& settings)
      : stratified_(settings.spp, settings.seed), sobol_(settings.seed), kind_(settings.sampler) {}

  SamplerKind kind() const { return kind_; }
  // The stratified sampler serves Whitted's area-light samples and the pixel offsets under
  // render.sampler: stratified whatever the integrator.
  const StratifiedSampler& stratified() const { return stratified_; }
  const SobolSampler& sobol() const { return sobol_; }

  // f(sampler) with the sampler render.sampler chooses.
  template <class F>
  decltype(auto) with_chosen(F&& f) const {
    switch (kind_) {
      case SamplerKind::kStratified: return f(stratified_);
      case SamplerKind::kSobol: return f(sobol_);
    }
    __builtin_unreachable();  // the switch covers every kind
  }

 private:
  StratifiedSampler stratified_;
  SobolSampler sobol_;
  SamplerKind kind_;
};

}  // namespace rtpro
