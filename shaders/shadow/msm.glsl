// Moment shadow mapping (Peters & Klein, "Moment Shadow Mapping", I3D 2015).
//
// Convention: the moments are those of the signed depth u = 2 z - 1 in
// [-1, 1], b = (E[u], E[u^2], E[u^3], E[u^4]), where z in [0, 1] is the
// relative occluder depth; msm_moments() makes them from a depth, and the
// receiver's relative depth z_f goes in as msm_signed_depth(z_f). This is
// the convention of Peters' later code (Peters, Münstermann, Wetzstein and
// Klein, "Improved Moment Shadow Maps for Translucent Occluders, Soft
// Shadows and Single Scattering", JCGT 2017), and it matters in float:
// near the far end (z -> 1) the moments of z are all nearly 1 and float32
// keeps little of their differences, while those of u spread the same
// depths twice as wide (4 times the variance, 16 times the fourth-order
// terms the solve divides by) for the same rounding. The Hamburger bound
// itself does not change under an affine map of the depth axis (it maps
// distributions with given moments onto distributions with the mapped
// moments), so only the rounding differs. msm_hamburger() returns the
// shadow intensity G (0 = lit, 1 = shadowed); the lit fraction is 1 - G.
//
// 16-bit storage: msm_quantize() / msm_dequantize() wrap the optimized
// invertible affine transform of seed 002 (the form Peters presented at
// GDC 2016), which is defined on the moments of u; the I3D 2015 paper's own
// matrix (-2.07224649, 13.7948857237, ...) targets [0, 1]. The dequantized
// moments stay moments of u: converting them back to moments of z in float
// (as this code once did) moved G by up to 0.11 at filtered edges near the
// far end (tests/gpu/moment_shader_test.cpp).
#pragma once

// The signed depth u = 2 z - 1 of a relative depth z. Exact in float for
// z in [0.25, 1] (2 z is exact and 2 z - 1 is then exact by Sterbenz's lemma).
float msm_signed_depth(float z) {
  return fma(2.0, z, -1.0);
}

// Back from u to z, for the mean depth of filtered moments.
float msm_unit_depth(float u) {
  return fma(0.5, u, 0.5);
}

// The four moments a texel at relative depth z stores: (u, u^2, u^3, u^4)
// with u = 2 z - 1: the four power moments of Peters & Klein 2015, of the
// signed depth as in Peters' JCGT 2017 code.
vec4 msm_moments(float z) {
  float u = msm_signed_depth(z);
  float u2 = u * u;
  return vec4(u, u2, u2 * u, u2 * u2);
}

// Bias vectors b_bias of Algorithm 3 step 1, as moments of u.
// 32-bit: Peters' later code's (0, 0.375, 0, 0.375) (JCGT 2017 / HPG 2017
// supplementary code), the moments of 0.1875 at u = -1 and at u = 1 and
// 0.625 at u = 0.
const vec4 MSM_BIAS_32 = vec4(0.0, 0.375, 0.0, 0.375);
// 16-bit: Peters' (0, 0.628, 0, 0.628) for the optimized quantization (seed
// 002 rounds it to 0.63): 0.314 at u = -1 and at u = 1, 0.372 at u = 0.
const vec4 MSM_BIAS_16 = vec4(0.0, 0.628, 0.0, 0.628);

// Algorithm 3 (Hamburger 4MSM) of Peters & Klein 2015, in whatever depth
// variable the moments b are of (here u; the receiver z_f in the same one).
//   1. b' = (1 - alpha) b + alpha b_bias.
//   2. Solve the Hankel system [1 b1 b2; b1 b2 b3; b2 b3 b4] c = (1, z_f, z_f^2).
//   3. z2 <= z3: the roots of c3 z^2 + c2 z + c1.
//   4. G = 0 if z_f <= z2;
//   5. else if z_f <= z3: G = (z_f z3 - b1 (z_f + z3) + b2) / ((z3 - z2)(z_f - z2));
//   6. else G = 1 - (z2 z3 - b1 (z2 + z3) + b2) / ((z_f - z2)(z_f - z3)).
//
// Step 2 uses the square-root-free Cholesky factorization L D L^T of the
// Hankel matrix, as Peters' reference HLSL does:
//   L = [1 0 0; b1 1 0; b2 l32 1], D = diag(1, d22, d33), with
//   d22 = b2 - b1^2 = Var(z), l32 d22 = b3 - b1 b2 = Cov(z, z^2),
//   d33 d22 = Var(z) Var(z^2) - Cov(z, z^2)^2.
// All of the shadow's information is in these small differences of nearly
// equal moments, so in float we (a) form the covariances of the biased
// moments from those of b and of b_bias (the covariance of a mixture)
// instead of rounding b' first, with fma() for b's own, and (b) solve and
// evaluate steps 3-6 in the depth relative to the mean, t = z - b1', where
// every quantity is a central one. This is the same algebra; against a
// double-precision Cramer's-rule solve it keeps |dG| near the error that
// rounding the inputs themselves to float already causes.
//
// Every division and root is guarded so that degenerate input (constant
// depth, a receiver outside [-1, 1], alpha near 0, moments that are not
// those of any distribution) gives a finite G in [0, 1].
//
// msm_quadrature() does steps 1-3; msm_hamburger() steps 4-6, and
// msm_blocker_search() reads the mean blocker depth off the same
// quadrature (Peters et al. 2016).

// The three-point quadrature of steps 1-3, centred: every depth is
// t = z - mean, where mean = b1' is the biased moments' mean; the atoms sit
// at t2 <= t3 (the roots) and at the receiver y = z_f - mean; d22 is the
// biased variance E[t^2].
struct MsmQuadrature {
  float mean;
  float d22;
  float y;
  float t2;
  float t3;
};

MsmQuadrature msm_quadrature(vec4 b, float z_f, float alpha, vec4 bias_vector) {
  // Step 1, as covariances of (z, z^2) under (1 - alpha) P_b + alpha P_bias:
  // Cov' = (1 - alpha) Cov_b + alpha Cov_bias + alpha (1 - alpha) d d^T,
  // d = (b1, b2) - (bias1, bias2).
  float beta = 1.0 - alpha;
  vec2 d = b.xy - bias_vector.xy;
  vec4 p = bias_vector;
  float var_z = beta * fma(-b.x, b.x, b.y) + alpha * (fma(-p.x, p.x, p.y) + beta * d.x * d.x);
  float cov = beta * fma(-b.x, b.y, b.z) + alpha * (fma(-p.x, p.y, p.z) + beta * d.x * d.y);
  float var_z2 = beta * fma(-b.y, b.y, b.w) + alpha * (fma(-p.y, p.y, p.w) + beta * d.y * d.y);
  float mean = mix(b.x, p.x, alpha);

  // Step 2. d22 >= alpha Var(bias) > 0 for valid moments; the floor only
  // catches invalid input.
  float d22 = max(var_z, 1e-9);
  float l32 = cov / d22;
  // d33 d22 = var_z2 d22 - cov^2, with Kahan's fma form of a 2x2 determinant.
  float cov2 = cov * cov;
  float d33 = max(fma(var_z2, d22, -cov2) + fma(-cov, cov, cov2), 0.0) / d22;
  // Forward substitution L y = (1, z_f, z_f^2), centred:
  //   y2 = z_f - b1', y3 = z_f^2 - b2' - l32 y2 = y2 (y2 + s) - d22,
  // with s = 2 b1' - l32 = -E[t^3] / E[t^2].
  float y2 = (z_f - b.x) + alpha * d.x;
  float s = 2.0 * mean - l32;
  float y3 = y2 * (y2 + s) - d22;
  // Back substitution: c3 = y3 / d33, c2 = y2 / d22 - l32 c3,
  // c1 = 1 - b1' c2 - b2' c3. Only the roots matter, so we scale c by d33
  // (d33 is 0 for the moments of two depths, e.g. a bias vector of two
  // atoms, or alpha = 0 and a constant depth, where dividing by it gives
  // Inf/NaN),
  // and substitute z = b1' + t:
  //   P(t) = y3 t^2 + (y3 s + y2 d33 / d22) t + (d33 - y3 d22).
  vec3 c = vec3(d33 - y3 * d22, y3 * s + y2 * (d33 / d22), y3);  // (c1, c2, c3)
  if (max(max(abs(c.x), abs(c.y)), abs(c.z)) < 1e-30) {
    // y3 = d33 = 0: two depths and z_f on one of them. The limit is the
    // orthogonal polynomial t^2 + s t - d22, whose roots are the two depths
    // (P is y3 times it, plus d33 times a second polynomial).
    c = vec3(-d22, s, 1.0);
  }
  c /= max(max(abs(c.x), abs(c.y)), abs(c.z));
  // c3 -> 0 sends one root to infinity (z_f is then a node of the
  // two-point quadrature); |c3| >= 1e-7 keeps it finite, below ~1e7, with
  // a change of G of the order of 1e-7.
  c.z = c.z < 0.0 ? min(c.z, -1e-7) : max(c.z, 1e-7);

  // Step 3, in the cancellation-free form: q = -(c2 + sign(c2) sqrt(D)) / 2,
  // roots q / c3 and c1 / q. For valid moments the roots are real; a
  // negative discriminant can only come from rounding, and its real part
  // -c2 / (2 c3) is then the double root.
  float discriminant = c.y * c.y - 4.0 * c.x * c.z;
  float t2, t3;
  if (discriminant > 0.0) {
    float q = -0.5 * (c.y + (c.y < 0.0 ? -1.0 : 1.0) * sqrt(discriminant));
    float r1 = q / c.z;
    float r2 = c.x / q;  // |q| >= sqrt(discriminant) / 2 > 0
    t2 = clamp(min(r1, r2), -1e8, 1e8);
    t3 = clamp(max(r1, r2), -1e8, 1e8);
  } else {
    t2 = t3 = clamp(-0.5 * c.y / c.z, -1e8, 1e8);
  }

  return MsmQuadrature(mean, d22, y2, t2, t3);
}

// The quadrature's weights, from the Vandermonde system of its three atoms
// in t (z_f - z_i = y - t_i; z_f z3 - b1'(z_f + z3) + b2' = y t3 + d22;
// z2 z3 - b1'(z2 + z3) + b2' = t2 t3 + d22):
//   w2 (at t2) = (y t3 + d22) / ((t3 - t2)(y - t2)),
//   w_f (at y) = (t2 t3 + d22) / ((y - t2)(y - t3)), w3 = 1 - w2 - w_f.
// Each denominator is positive where it is used; the floor only guards
// against underflow.
float msm_weight_low(MsmQuadrature q) {
  return (q.y * q.t3 + q.d22) / max((q.t3 - q.t2) * (q.y - q.t2), 1e-20);
}

float msm_weight_receiver(MsmQuadrature q) {
  return (q.t2 * q.t3 + q.d22) / max((q.y - q.t2) * (q.y - q.t3), 1e-20);
}

float msm_hamburger(vec4 b, float z_f, float alpha, vec4 bias_vector) {
  MsmQuadrature q = msm_quadrature(b, z_f, alpha, bias_vector);
  // Steps 4-6: the weight of the atoms in front of the receiver (the
  // final clamp only catches rounding).
  if (q.y <= q.t2) return 0.0;
  float g = q.y <= q.t3 ? msm_weight_low(q) : 1.0 - msm_weight_receiver(q);
  return clamp(g, 0.0, 1.0);
}

// The blocker search of moment soft shadow mapping (Peters, Münstermann,
// Wetzstein and Klein, "Moment Soft Shadow Mapping", I3D 2016, and its
// JCGT 2017 extension): the mean depth of the blockers is that of the
// quadrature's atoms in front of the receiver, weighted by their weights,
//   z_avg = sum_{z_i < z_f} w_i z_i / sum_{z_i < z_f} w_i,
// with the receiver's own atom added at a tiny weight (1e-3, Peters'
// "fully lit bias") so that z_avg -> z_f, a zero-width penumbra, as the
// blockers' weight vanishes. Unlike assuming every unoccluded texel at the
// receiver's depth, this places the blockers where the moments say they
// are. Returns (z_avg, the blockers' weight, which is the shadow intensity
// G of msm_hamburger()), both in the moments' depth variable.
vec2 msm_blocker_search(vec4 b, float z_f, float alpha, vec4 bias_vector) {
  MsmQuadrature q = msm_quadrature(b, z_f, alpha, bias_vector);
  const float fully_lit_bias = 1e-3;
  float weight = 0.0, integral = 0.0;
  if (q.y > q.t2) {
    float w_low = clamp(msm_weight_low(q), 0.0, 1.0);
    weight = w_low;
    integral = w_low * q.t2;
    if (q.y > q.t3) {
      float w_high = clamp(1.0 - msm_weight_receiver(q) - w_low, 0.0, 1.0);
      weight += w_high;
      integral += w_high * q.t3;
    }
  }
  float t_avg = (fully_lit_bias * q.y + integral) / (fully_lit_bias + weight);
  return vec2(q.mean + min(t_avg, q.y), weight);
}

// The shadow intensity of a receiver at relative depth z_f (in [0, 1],
// like the depth maps) from filtered 32-bit float moments of u.
float msm_intensity32(vec4 b, float z_f, float alpha) {
  return msm_hamburger(b, msm_signed_depth(z_f), alpha, MSM_BIAS_32);
}

// The same from moments of u read back through msm_dequantize() (16-bit,
// or summed in the fixed-point summed-area table): the 16-bit bias vector.
float msm_intensity16(vec4 b, float z_f, float alpha) {
  return msm_hamburger(b, msm_signed_depth(z_f), alpha, MSM_BIAS_16);
}

// The optimized 16-bit quantization, for moments b = (E[u], .., E[u^4]) of
// u in [-1, 1] (seed 002, matrix form; its text form has the sign of the
// first row's u and u^3 terms flipped, which does not match the inverse):
//   R = 3/2 b1 - 2 b3 + 1/2        G = 4 b2 - 4 b4
//   B = sqrt(3)/2 b1 - sqrt(12)/9 b3 + 1/2       A = 1/2 b2 + 1/2 b4
// Each lies in [0, 1] for a point mass at any u in [-1, 1], hence for any
// mixture; it spreads the moments over the 16-bit range far better than
// storing them directly.
// GLSL matrices are column-major: each vec4 below is one column.
const mat4 MSM_QUANTIZE = mat4(1.5, 0.0, 0.8660254037844386, 0.0,    // b1
                               0.0, 4.0, 0.0, 0.5,                   // b2
                               -2.0, 0.0, -0.3849001794597505, 0.0,  // b3
                               0.0, -4.0, 0.0, 0.5);                 // b4
const vec4 MSM_QUANTIZE_OFFSET = vec4(0.5, 0.0, 0.5, 0.0);
// Its inverse (as printed in seed 002, and checked in double by the tests).
const mat4 MSM_DEQUANTIZE = mat4(-1.0 / 3.0, 0.0, -0.75, 0.0,                      // R
                                 0.0, 0.125, 0.0, -0.125,                         // G
                                 1.7320508075688772, 0.0, 1.299038105676658, 0.0,  // B
                                 0.0, 1.0, 0.0, 1.0);                             // A

// Moments of u -> the four values stored in an RGBA16 UNORM texel.
vec4 msm_quantize(vec4 b) {
  return clamp(MSM_QUANTIZE * b + MSM_QUANTIZE_OFFSET, 0.0, 1.0);
}

// A (filtered) RGBA16 UNORM texel -> moments of u for msm_intensity16().
vec4 msm_dequantize(vec4 q) {
  return MSM_DEQUANTIZE * (q - MSM_QUANTIZE_OFFSET);
}

// Moments of u -> moments of z = (u + 1) / 2 (binomial expansion of
// E[(u + 1)^k] / 2^k), for showing msm's maps as the moments of depth.
vec4 msm_moments_from_signed(vec4 b) {
  return vec4((b.x + 1.0) * 0.5, (b.y + 2.0 * b.x + 1.0) * 0.25,
              (b.z + 3.0 * b.y + 3.0 * b.x + 1.0) * 0.125,
              (b.w + 4.0 * b.z + 6.0 * b.y + 4.0 * b.x + 1.0) * 0.0625);
}
