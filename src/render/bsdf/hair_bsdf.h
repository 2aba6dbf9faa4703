#pragma once
// Chiang et al.'s hair BSDF (2016, "A Practical and Controllable Hair and Fur Model for Production
// Path Tracing"), as pbrt-v4's HairBxDF has it: a dielectric cylinder of index η and absorption σa
// (per unit of the fibre's radius) whose light leaves by R (reflected at the surface), TT (through
// the fibre), TRT (once reflected inside) and the residual of all longer paths, each lobe
// M_p(θ)·A_p·N_p(φ) (render/bsdf/hair_lobes.h). β_m widens the lobes along the fibre, β_n around
// it; the cuticle's scales, tilted by α, shift R by −2α, TT by α and TRT by 4α along the fibre.
// Sampling picks a lobe by its share of the attenuation (averaged over the channels), then θ from
// M_p and φ from N_p; pdf() is the same mixture's density.
//
// Angles are the fibre's: θ from the plane normal to its axis (sin θ = w·axis), φ around it, from
// normal × axis towards the shading normal (only φi − φo matters). The fibre's axis is a unit
// vector in the shading frame's xy plane; the offset h in [−1, 1] says where across its width the
// ray hit (pbrt's h: the hit's offset from the axis over the radius, along axis × ray direction).
// Without an offset (surfaces that are not curves) h is where a cylinder about the axis with the
// shading normal at the hit would have been hit from wo: −(w·(normal × axis)) / cos θo.
//
// eval() returns the model's scattering function over the shading frame's |cos θi|, which the
// path integrator multiplies back: a fibre's scattering does not fall off with the cosine to a
// surface normal.
#include "bsdf_from.h"
#include "bsdf_sample.h"
#include "hair_lobes.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace rtpro {

class HairBsdf {
 public:
  struct Fibre {
    float eta = 1.55f;
    Color sigma_a{0.0f};
    float beta_m = 0.3f, beta_n = 0.3f;
    float alpha_degrees = 2.0f;
  };
  // `axis_x`, `axis_y`: the fibre's unit axis in the shading frame (its z is 0). `offset`: h, or
  // NaN to take it from wo (above).
  HairBsdf(const Fibre& fibre, float axis_x, float axis_y, float offset);
  static constexpr float kOffsetFromWo = std::numeric_limits<float>::quiet_NaN();

  // The fibre's axis in the shading frame.
  Vec3 axis() const { return {axis_x_, axis_y_, 0.0f}; }
  float beta_m() const { return beta_m_; }
  float beta_n() const { return beta_n_; }
  bool is_delta() const { return false; }
  // Cycles' Filter Glossy for hair: β_m and β_n raised to at least min_alpha (render/bsdf/bsdf.h).
  void roughen_to(float min_alpha);
  // It scatters the same from either side of the surface: the frame's +z may face the ray.
  bool needs_outward_frame() const { return false; }

  Color eval(const Vec3& wo, const Vec3& wi) const;
  float pdf(const Vec3& wo, const Vec3& wi) const;
  // u_lobe picks the lobe and, rescaled, N_p's azimuth; u picks M_p's θ. R is a glossy bounce,
  // the lobes that crossed the fibre transmission (Cycles' labels).
  std::optional<BsdfSample> sample(const Vec3& wo, float u_lobe, Sample2D u) const;

  // A_p summed over the lobes for wo: what f·|cos θi| integrates to over the sphere (1 without
  // absorption).
  Color attenuation(const Vec3& wo) const;

 private:
  // What eval, pdf and sample need of wo alone, in the fibre's frame.
  struct Outgoing {
    float sin_o, cos_o, phi_o;
    float gamma_o, gamma_t;
    std::array<Color, kHairLobes> a;         // A_p
    std::array<float, kHairLobes> a_choice;  // the chance of sampling lobe p: its share of ΣA_p
  };
  Vec3 to_fibre(const Vec3& w) const { return {w.x * axis_x_ + w.y * axis_y_, w.y * axis_x_ - w.x * axis_y_, w.z}; }
  Vec3 from_fibre(const Vec3& w) const { return {w.x * axis_x_ - w.y * axis_y_, w.x * axis_y_ + w.y * axis_x_, w.z}; }
  void set_roughness(float beta_m, float beta_n);
  Outgoing outgoing(const Vec3& wo_fibre) const;
  // sin θ'o and |cos θ'o| of wo turned by lobe p's cuticle tilt.
  void tilted(const Outgoing& o, int p, float& sin_o, float& cos_o) const;
  // M_p·N_p of each lobe for wi (fibre frame).
  std::array<float, kHairLobes> lobes(const Outgoing& o, const Vec3& wi_fibre) const;

  float axis_x_, axis_y_;
  float offset_;
  float eta_;
  Color sigma_a_;
  float beta_m_, beta_n_;
  std::array<float, kHairLobes> v_;  // M_p's variance
  float s_;                          // N_p's logistic scale
  // sin and cos of each lobe's shift: −2α, α, 4α, 0.
  std::array<float, kHairLobes> shift_sin_, shift_cos_;
};

struct HairSurface;  // scene/hair_material.h

// As render/bsdf/bsdf_from.h asks of every kind: the fibre along SurfacePoint::tangent (its part
// normal to the shading normal; any tangent where that is nothing), with h = fiber_offset where it
// is not 0 and otherwise from wo; σa from the colour at the point when the material gave a colour.
Vec3 bsdf_from(const HairSurface& model, const ColorTexture& base_color, const SurfacePoint& point,
               const TextureLookup* textures, SurfaceBsdf& out);
inline bool makes_lambert_bsdf(const HairSurface&) { return false; }

}  // namespace rtpro
