#pragma once
// The factors of Chiang et al.'s hair model (2016), as pbrt-v4's HairBxDF has them, each a
// function of the angles in the fibre's frame (render/bsdf/hair_bsdf.h): the longitudinal
// scattering M_p of d'Eon et al. (2011), a von Mises-Fisher distribution over θi normalised for
// every θo; the azimuthal scattering N_p, a logistic about the direction a ray leaves the
// cylinder after p internal paths; and the attenuation A_p of each path by Fresnel and absorption.
#include "rtpro/core/vec3.h"

#include <array>

namespace rtpro {

// Paths scattered with p = 0 (R), 1 (TT) and 2 (TRT) internal segments get lobes of their own;
// p = kHairLobes - 1 stands for all longer ones together.
inline constexpr int kHairLobes = 4;

// The modified Bessel function I0, and its logarithm (asymptotic for large x, where I0 overflows).
float bessel_i0(float x);
float log_bessel_i0(float x);

// M_p(θi, θo) for variance v, per radian of θi with the cos θi of the solid angle included: it
// integrates to 1 over θi in [−π/2, π/2] against cos θi dθi. Below v = 0.1 in a logarithmic form,
// where sinh(1/v) and I0 overflow.
float longitudinal_scattering(float cos_i, float cos_o, float sin_i, float sin_o, float v);
// cos θ of a direction drawn from M_p about the specular cone, given u in [0, 1).
float sample_longitudinal_cosine(float u, float v);

// The logistic distribution of scale s restricted to [−π, π] and renormalised, and its sampling
// by inversion.
float trimmed_logistic(float x, float s);
float sample_trimmed_logistic(float u, float s);
// The azimuth at which a path of p internal segments leaves the fibre (relative to φo), for the
// offset angles γo outside and γt inside.
float exit_azimuth(int p, float gamma_o, float gamma_t);
// N_p(Δφ): the logistic of scale s about exit_azimuth, Δφ − that azimuth wrapped into [−π, π].
float azimuthal_scattering(float dphi, int p, float s, float gamma_o, float gamma_t);

// A_p for the fibre seen at cos θo with offset h (cos γo = sqrt(1 − h²)) and a transmittance T of
// one crossing: Fresnel reflection f at the first surface, (1 − f)² T f^(p−1) after p segments,
// and the geometric sum of all longer paths in the last.
std::array<Color, kHairLobes> hair_attenuation(float cos_theta_o, float eta, float h, const Color& transmittance);

// The longitudinal variance v of β_m for each lobe (wider for longer paths) and the logistic scale
// s of β_n, Chiang et al.'s fits to path-traced fibres.
std::array<float, kHairLobes> longitudinal_variances(float beta_m);
float azimuthal_scale(float beta_n);

}  // namespace rtpro
