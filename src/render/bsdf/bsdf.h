#pragma once
// The closed set of BSDF kinds the path tracer shades with, each a file pair of its own with the
// members eval, pdf, sample, is_delta and needs_outward_frame, and beside them what the material
// kind that makes it declares (render/bsdf/bsdf_from.h). Registering a kind is its include and, for a BSDF, its
// alternative below; the static_asserts here and in render/bsdf/material_bsdf.h name what it
// lacks. All directions are in the local shading frame (render/surface/shading_frame.h),
// conventions in render/bsdf/bsdf_sample.h.
#include "bsdf_sample.h"
#include "conductor_bsdf.h"
#include "dielectric_bsdf.h"
#include "diffuse_bsdf.h"
#include "hair_bsdf.h"
#include "interface_bsdf.h"
#include "phong_bsdf.h"
#include "principled_bsdf.h"

#include <concepts>
#include <cstddef>
#include <optional>
#include <utility>
#include <variant>

namespace rtpro {

using Bsdf = std::variant<DiffuseBsdf, ConductorBsdf, DielectricBsdf, PrincipledBsdf, PhongBsdf, HairBsdf>;

// Every member the dispatch below calls, each by name, so that a BSDF missing one stops the build
// with what it lacks rather than in the visits that call it.
template <typename B>
constexpr bool has_bsdf_members() {
  static_assert(
      requires(const B& b, const Vec3& w) {
        { b.eval(w, w) } -> std::same_as<Color>;
      },
      "a BSDF needs `Color eval(const Vec3& wo, const Vec3& wi) const`");
  static_assert(
      requires(const B& b, const Vec3& w) {
        { b.pdf(w, w) } -> std::same_as<float>;
      },
      "a BSDF needs `float pdf(const Vec3& wo, const Vec3& wi) const`");
  static_assert(
      requires(const B& b, const Vec3& w, float u_lobe, Sample2D u) {
        { b.sample(w, u_lobe, u) } -> std::same_as<std::optional<BsdfSample>>;
      },
      "a BSDF needs `std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const`");
  static_assert(
      requires(const B& b) {
        { b.is_delta() } -> std::same_as<bool>;
      },
      "a BSDF needs `bool is_delta() const`");
  static_assert(
      requires(B & b, float min_alpha) {
        { b.roughen_to(min_alpha) } -> std::same_as<void>;
      },
      "a BSDF needs `void roughen_to(float min_alpha)`: its microfacet lobes' α raised to at least min_alpha");
  static_assert(
      requires(const B& b) {
        { b.needs_outward_frame() } -> std::same_as<bool>;
      },
      "a BSDF needs `bool needs_outward_frame() const`: whether +z of its frame must be the outside");
  return true;
}

template <std::size_t... Kind>
constexpr bool every_bsdf_has_members(std::index_sequence<Kind...>) {
  return (has_bsdf_members<std::variant_alternative_t<Kind, Bsdf>>() && ...);
}
static_assert(every_bsdf_has_members(std::make_index_sequence<std::variant_size_v<Bsdf>>{}));

// f(wo, wi) without the cosine; 0 for delta BSDFs, whose lobes only sampling can find.
Color bsdf_eval(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi);
// Density of bsdf_sample choosing wi, per unit solid angle; 0 for delta BSDFs.
float bsdf_pdf(const Bsdf& bsdf, const Vec3& wo, const Vec3& wi);
// A direction wi for wo: u_lobe chooses among lobes, u places the direction within one.
std::optional<BsdfSample> bsdf_sample(const Bsdf& bsdf, const Vec3& wo, float u_lobe, Sample2D u);
// Every microfacet lobe's GGX α raised to at least min_alpha, a smooth lobe's from 0 (Cycles'
// Filter Glossy: render/integrators/path_integrator.cpp says when and by how much).
inline void roughen_bsdf(Bsdf& bsdf, float min_alpha) {
  std::visit([&](auto& b) { b.roughen_to(min_alpha); }, bsdf);
}
// True when every lobe is specular: sampling a light there can never be weighted in. Inline: every
// path vertex asks, and for most kinds the answer is a comparison or a constant.
inline bool bsdf_is_delta(const Bsdf& bsdf) {
  return std::visit([](const auto& b) { return b.is_delta(); }, bsdf);
}

}  // namespace rtpro
