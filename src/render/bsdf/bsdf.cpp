#include "bsdf.h"

#include <variant>

namespace rtpro {

// Each kind's own members, no fallback (bsdf.h asks each kind for them).
Color bsdf_eval(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  return std::visit([&](const auto& b) { return b.eval(wo, wi); }, bsdf);
}

float bsdf_pdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi) {
  return std::visit([&](const auto& b) { return b.pdf(wo, wi); }, bsdf);
}

std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, const Vec3& wo, float u_lobe, Sample2D u) {
  return std::visit([&](const auto& b) { return b.sample(wo, u_lobe, u); }, bsdf);
}

}  // namespace rtpro
