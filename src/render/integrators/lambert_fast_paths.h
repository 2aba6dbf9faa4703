#pragma once
// The path integrator's BSDF calls, with the fast paths of Lambert surfaces (most vertices of most
// scenes): f inline, and the sample from the cosine direction drawn with the vertex's random
// numbers (vertex_samples.h). Each gives what bsdf_eval and bsdf_sample give, bit for bit.
#include "bsdf.h"
#include "vertex_samples.h"

#include <optional>
#include <variant>

namespace rtpro {

// bsdf_eval; a Lambert surface's f is a comparison and a product, less than the call.
inline Color eval_bsdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  if (const auto* lambert = std::get_if<DiffuseBsdf>(&bsdf)) return lambert->eval(wo, wi);
  return bsdf_eval(bsdf, wo, wi);
}

// bsdf_sample with the vertex's numbers; a Lambert surface's from its direction worked out
// beforehand when `cosine_directions` (VertexDraws::cosine_directions).
inline std::optional<BsdfSample> sample_bsdf(const Bsdf& bsdf, const Vec3& wo, const VertexSamples& u,
                                             bool cosine_directions) {
  if (const auto* lambert = std::get_if<DiffuseBsdf>(&bsdf); lambert && cosine_directions)
    return lambert->sample_toward(wo, u.cosine_direction);
  return bsdf_sample(bsdf, wo, u.choices.y, u.bsdf_direction);
}

}  // namespace rtpro
