#include "rtpro/render/bsdf.h"

#include "rtpro/core/overloaded.h"

namespace rtpro {

// One lambda per kind, no generic fallback: a kind added to Bsdf must be handled here.
Color bsdf_eval(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  return std::visit(Overloaded{[&](const DiffuseBsdf& b) { return b.eval(wo, wi); },
                               [&](const ConductorBsdf& b) { return b.eval(wo, wi); },
                               [&](const DielectricBsdf& b) { return b.eval(wo, wi); },
                               [&](const PrincipledBsdf& b) { return b.eval(wo, wi); }},
                    bsdf);
}

float bsdf_pdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  return std::visit(Overloaded{[&](const DiffuseBsdf& b) { return b.pdf(wo, wi); },
                               [&](const ConductorBsdf& b) { return b.pdf(wo, wi); },
                               [&](const DielectricBsdf& b) { return b.pdf(wo, wi); },
                               [&](const PrincipledBsdf& b) { return b.pdf(wo, wi); }},
                    bsdf);
}

std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, const Vec3& wo, float u_lobe, Sample2D u) {
  return std::visit(Overloaded{[&](const DiffuseBsdf& b) { return b.sample(wo, u_lobe, u); },
                               [&](const ConductorBsdf& b) { return b.sample(wo, u_lobe, u); },
                               [&](const DielectricBsdf& b) { return b.sample(wo, u_lobe, u); },
                               [&](const PrincipledBsdf& b) { return b.sample(wo, u_lobe, u); }},
                    bsdf);
}

bool bsdf_is_delta(const Bsdf& bsdf) {
  return std::visit(Overloaded{[](const DiffuseBsdf& b) { return b.is_delta(); },
                               [](const ConductorBsdf& b) { return b.is_delta(); },
                               [](const DielectricBsdf& b) { return b.is_delta(); },
                               [](const PrincipledBsdf& b) { return b.is_delta(); }},
                    bsdf);
}

}  // namespace rtpro
