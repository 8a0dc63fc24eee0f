// Moment shadow mapping (Peters & Klein, "Moment Shadow Mapping", I3D 2015).
//
// Convention: b = (E[z], E[z^2], E[z^3], E[z^4]), the filtered moments of
// the relative occluder depth z in [0, 1], and z_f the receiver's relative
// depth. msm_hamburger() returns the shadow intensity G (0 = lit,
// 1 = shadowed); the lit fraction is 1 - G.
//
// 16-bit storage: msm_quantize() / msm_dequantize() wrap an optimized
// invertible affine transform of the moments that spreads them over the
// UNORM range. We use the matrix of seed 002 (the form Peters presented at
// GDC 2016), which is defined for depths z' in [-1, 1]; the I3D 2015
// paper's own matrix (-2.07224649, 13.7948857237, ...) targets [0, 1]. We
// apply it to the moments of z' = 2z - 1 and convert back, so the interface
// and the Hamburger solve stay in the [0, 1] convention throughout.
#pragma once

// Bias vectors b_bias of Algorithm 3 step 1, as moments of z in [0, 1].
// 32-bit: Peters' (0.5, 0.5, 0.5, 0.5), the moments of half the mass at 0
// and half at 1.
const vec4 MSM_BIAS_32 = vec4(0.5, 0.5, 0.5, 0.5);
// 16-bit: Peters biases the [-1, 1] moments toward (0, 0.628, 0, 0.628)
// (masses 0.314 at -1 and at 1, 0.372 at 0). The same distribution in
// z = (z' + 1) / 2: E[z^k] = E[(z' + 1)^k] / 2^k by the binomial expansion,
// (0.5, (0.628 + 1) / 4, (3 * 0.628 + 1) / 8, (7 * 0.628 + 1) / 16).
// Since the moments of a mixture are the mixture of the moments, biasing
// here is exactly biasing in [-1, 1].
const vec4 MSM_BIAS_16 = vec4(0.5, 0.407, 0.3605, 0.33725);

// Algorithm 3 (Hamburger 4MSM) of Peters & Klein 2015.
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
// depth, a receiver outside [0, 1], alpha near 0, moments that are not
// those of any distribution) gives a finite G in [0, 1].
float msm_hamburger(vec4 b, float z_f, float alpha, vec4 bias_vector) {
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
  // (d33 is 0 for the moments of two depths, e.g. a constant depth of 0
  // or 1 biased toward MSM_BIAS_32, where dividing by it gives Inf/NaN),
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

  // Steps 4-6 in t (z_f - z_i = y2 - t_i; z_f z3 - b1'(z_f + z3) + b2' =
  // y2 t3 + d22; z2 z3 - b1'(z2 + z3) + b2' = t2 t3 + d22). Both
  // denominators are positive in their branches; the floor only guards
  // against underflow, and the final clamp against rounding.
  if (y2 <= t2) return 0.0;
  float g;
  if (y2 <= t3) {
    g = (y2 * t3 + d22) / max((t3 - t2) * (y2 - t2), 1e-20);
  } else {
    g = 1.0 - (t2 * t3 + d22) / max((y2 - t2) * (y2 - t3), 1e-20);
  }
  return clamp(g, 0.0, 1.0);
}

// 32-bit float moments: Peters' bias vector.
float msm_hamburger(vec4 b, float z_f, float alpha) {
  return msm_hamburger(b, z_f, alpha, MSM_BIAS_32);
}

// Moments read back through msm_dequantize(): the 16-bit bias vector.
float msm_hamburger16(vec4 b, float z_f, float alpha) {
  return msm_hamburger(b, z_f, alpha, MSM_BIAS_16);
}

// The optimized 16-bit quantization, for moments u = (E[z'], .., E[z'^4])
// of z' in [-1, 1] (seed 002, matrix form; its text form has the sign of
// the first row's z and z^3 terms flipped, which does not match the
// inverse):
//   R = 3/2 u1 - 2 u3 + 1/2        G = 4 u2 - 4 u4
//   B = sqrt(3)/2 u1 - sqrt(12)/9 u3 + 1/2       A = 1/2 u2 + 1/2 u4
// Each lies in [0, 1] for a point mass at any z' in [-1, 1], hence for any
// mixture; it spreads the moments over the 16-bit range far better than
// storing them directly.
// GLSL matrices are column-major: each vec4 below is one column.
const mat4 MSM_QUANTIZE = mat4(1.5, 0.0, 0.8660254037844386, 0.0,    // u1
                               0.0, 4.0, 0.0, 0.5,                   // u2
                               -2.0, 0.0, -0.3849001794597505, 0.0,  // u3
                               0.0, -4.0, 0.0, 0.5);                 // u4
const vec4 MSM_QUANTIZE_OFFSET = vec4(0.5, 0.0, 0.5, 0.0);
// Its inverse (as printed in seed 002, and checked in double by the tests).
const mat4 MSM_DEQUANTIZE = mat4(-1.0 / 3.0, 0.0, -0.75, 0.0,                      // R
                                 0.0, 0.125, 0.0, -0.125,                         // G
                                 1.7320508075688772, 0.0, 1.299038105676658, 0.0,  // B
                                 0.0, 1.0, 0.0, 1.0);                             // A

// Moments of z in [0, 1] -> moments of z' = 2z - 1 (binomial expansion).
vec4 msm_moments_to_signed(vec4 b) {
  return vec4(2.0 * b.x - 1.0,
              4.0 * b.y - 4.0 * b.x + 1.0,
              8.0 * b.z - 12.0 * b.y + 6.0 * b.x - 1.0,
              16.0 * b.w - 32.0 * b.z + 24.0 * b.y - 8.0 * b.x + 1.0);
}

// Moments of z' in [-1, 1] -> moments of z = (z' + 1) / 2.
vec4 msm_moments_from_signed(vec4 u) {
  return vec4((u.x + 1.0) * 0.5,
              (u.y + 2.0 * u.x + 1.0) * 0.25,
              (u.z + 3.0 * u.y + 3.0 * u.x + 1.0) * 0.125,
              (u.w + 4.0 * u.z + 6.0 * u.y + 4.0 * u.x + 1.0) * 0.0625);
}

// [0, 1]-depth moments -> the four values stored in an RGBA16 UNORM texel.
vec4 msm_quantize(vec4 b) {
  return clamp(MSM_QUANTIZE * msm_moments_to_signed(b) + MSM_QUANTIZE_OFFSET, 0.0, 1.0);
}

// A (filtered) RGBA16 UNORM texel -> [0, 1]-depth moments for msm_hamburger16().
vec4 msm_dequantize(vec4 q) {
  return msm_moments_from_signed(MSM_DEQUANTIZE * (q - MSM_QUANTIZE_OFFSET));
}
