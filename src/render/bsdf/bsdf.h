#pragma once
// The closed set of BSDF kinds the path tracer shades with, each a file pair of its own with the
// members eval, pdf, sample, is_delta and needs_outward_frame, and beside them the bsdf_from of the
// material kind that makes it (a kind without a BSDF of its own, phong, has a file pair for its
// bsdf_from alone). Registering a kind is its include and, for a BSDF, its alternative below; the
// dispatch (bsdf.cpp, material_bsdf.cpp) names a member or a bsdf_from it lacks. All directions
// are in the local shading frame (render/surface/shading_frame.h), conventions in render/bsdf/bsdf_sample.h.
#include "bsdf_sample.h"
#include "conductor_bsdf.h"
#include "dielectric_bsdf.h"
#include "diffuse_bsdf.h"
#include "phong_bsdf.h"
#include "principled_bsdf.h"

#include <optional>
#include <variant>

namespace rtpro {

using Bsdf = std::variant<DiffuseBsdf, ConductorBsdf, DielectricBsdf, PrincipledBsdf>;

// f(wo, wi) without the cosine; 0 for delta BSDFs, whose lobes only sampling can find.
Color bsdf_eval(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi);
// Density of bsdf_sample choosing wi, per unit solid angle; 0 for delta BSDFs.
float bsdf_pdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi);
// A direction wi for wo: u_lobe chooses among lobes, u places the direction within one.
std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, const Vec3& wo, float u_lobe, Sample2D u);
// True when every lobe is specular: sampling a light there can never be weighted in. Inline: every
// path vertex asks, and for most kinds the answer is a comparison or a constant.
inline bool bsdf_is_delta(const Bsdf& bsdf) {
  return std::visit([](const auto& b) { return b.is_delta(); }, bsdf);
}

}  // namespace rtpro
