#pragma once
// Double-precision references for the shadow factors of the filterable
// techniques (shaders/shadow/{vsm,esm,msm}.glsl), written independently of
// the shaders' structure so that the tests compare two derivations, and
// float mirrors of the 16-bit MSM quantization.
//
// Conventions as in the shaders: relative depth z in [0, 1]; MSM moments
// are those of the signed depth u = 2 z - 1, b = (E[u], .., E[u^4]).
#include <glm/glm.hpp>

namespace penumbra {

// The moments (u, u^2, u^3, u^4), u = 2 z - 1, of one relative depth z (what
// msm_moments() in msm.glsl stores per texel), in double.
constexpr glm::dvec4 msm_moments_of_depth(double z) {
  const double u = 2.0 * z - 1.0;
  return {u, u * u, u * u * u, u * u * u * u};
}

// Moments of u in [-1, 1] -> moments of z = (u + 1) / 2 (binomial
// expansion of E[(u + 1)^k] / 2^k).
constexpr glm::dvec4 msm_moments_from_signed(const glm::dvec4& u) {
  return {(u.x + 1.0) / 2.0, (u.y + 2.0 * u.x + 1.0) / 4.0,
          (u.z + 3.0 * u.y + 3.0 * u.x + 1.0) / 8.0,
          (u.w + 4.0 * u.z + 6.0 * u.y + 4.0 * u.x + 1.0) / 16.0};
}

// Bias vectors of Algorithm 3, step 1 (Peters & Klein, I3D 2015), as
// moments of u. 32-bit float moments: (0, 0.375, 0, 0.375), Peters' later
// code's (JCGT 2017): 0.1875 at u = -1 and at 1, 0.625 at 0.
inline constexpr glm::dvec4 kMsmBias32{0.0, 0.375, 0.0, 0.375};
// 16-bit quantized moments: Peters' (0, 0.628, 0, 0.628) (seed 002): 0.314
// at u = -1 and at 1, 0.372 at 0.
inline constexpr glm::dvec4 kMsmBias16{0.0, 0.628, 0.0, 0.628};

// Hamburger 4MSM shadow intensity G (0 = lit, 1 = shadowed), Algorithm 3 of
// Peters & Klein 2015, with the 3x3 Hankel system solved by Cramer's rule
// and the quadratic by the textbook formula, for moments b and a receiver
// z_f in the same depth variable (u for the shaders' moments). The result
// is clamped to [0, 1] like the shader's.
double msm_hamburger_reference(glm::dvec4 b, double z_f, double alpha,
                               glm::dvec4 bias_vector = kMsmBias32);

// Variance shadow map lit fraction (Donnelly & Lauritzen 2006): 1 if
// z_f <= mean, else the Chebyshev bound with variance >= min_variance,
// passed through the light-bleeding reduction linstep(amount, 1, p).
double vsm_reference(glm::dvec2 moments, double receiver_depth, double min_variance,
                     double bleed_reduction);

// Light-bleeding reduction: linstep(amount, 1, lit).
double reduce_light_bleeding_reference(double lit, double amount);

// Exponential shadow map lit fraction (Annen et al. 2008) for a filtered
// value of the shifted encoding exp(c (z - 1)), floored at exp(-c) (the
// encoding of depth 0) like the shader: min(1, f exp(-c (z_f - 1))).
double esm_reference(double filtered, double receiver_depth, double c);

// Exponential variance shadow maps (Lauritzen & McCool, GI 2008): the
// warps p = exp(c+ u) and n = -exp(-c- u) of relative depth z, u = 2 z - 1.
glm::dvec2 evsm_warp_reference(double z, double positive_exponent, double negative_exponent);

// EVSM lit fraction for filtered warped moments m = (E[p], E[p^2], E[n],
// E[n^2]) (evsm2: m.z, m.w unused) and receiver z: in each warp w,
// Chebyshev's one-tailed bound with the variance floored at the warp of the
// z-bar floor min_variance, (dw/dz)^2 min_variance = (2 c w)^2 min_variance;
// evsm4 takes the smaller bound.
double evsm_reference(glm::dvec4 m, double z, double positive_exponent, double negative_exponent,
                      double min_variance, bool four);

// Float mirrors of msm_quantize() / msm_dequantize() in msm.glsl: moments
// of u <-> the four RGBA16 UNORM values (seed 002's transform).
glm::vec4 msm_quantize(glm::vec4 b);
glm::vec4 msm_dequantize(glm::vec4 q);

}  // namespace penumbra
