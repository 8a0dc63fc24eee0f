#include "penumbra/shadow/moment_math.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

// det[a b c] for column vectors a, b, c.
double det3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return a.x * (b.y * c.z - b.z * c.y) + a.y * (b.z * c.x - b.x * c.z) +
         a.z * (b.x * c.y - b.y * c.x);
}

}  // namespace

double msm_hamburger_reference(glm::dvec4 b, double z_f, double alpha, glm::dvec4 bias_vector) {
  // 1. Pull the moments toward the bias vector.
  const glm::dvec4 m = (1.0 - alpha) * b + alpha * bias_vector;
  // 2. Cramer's rule on the symmetric Hankel matrix with columns A, B, C.
  const glm::dvec3 col_a{1.0, m.x, m.y};
  const glm::dvec3 col_b{m.x, m.y, m.z};
  const glm::dvec3 col_c{m.y, m.z, m.w};
  const glm::dvec3 rhs{1.0, z_f, z_f * z_f};
  const double d = det3(col_a, col_b, col_c);
  const double c1 = det3(rhs, col_b, col_c) / d;
  const double c2 = det3(col_a, rhs, col_c) / d;
  const double c3 = det3(col_a, col_b, rhs) / d;
  // 3. Roots z2 <= z3 of c3 z^2 + c2 z + c1.
  const double root = std::sqrt(std::max(c2 * c2 - 4.0 * c3 * c1, 0.0));
  double z2 = (-c2 - root) / (2.0 * c3);
  double z3 = (-c2 + root) / (2.0 * c3);
  if (z2 > z3) std::swap(z2, z3);
  // 4.-6.
  double g;
  if (z_f <= z2) {
    g = 0.0;
  } else if (z_f <= z3) {
    g = (z_f * z3 - m.x * (z_f + z3) + m.y) / ((z3 - z2) * (z_f - z2));
  } else {
    g = 1.0 - (z2 * z3 - m.x * (z2 + z3) + m.y) / ((z_f - z2) * (z_f - z3));
  }
  return std::clamp(g, 0.0, 1.0);
}

double reduce_light_bleeding_reference(double lit, double amount) {
  if (amount <= 0.0) return std::clamp(lit, 0.0, 1.0);
  if (amount >= 1.0) return lit >= 1.0 ? 1.0 : 0.0;
  return std::clamp((lit - amount) / (1.0 - amount), 0.0, 1.0);
}

double vsm_reference(glm::dvec2 moments, double receiver_depth, double min_variance,
                     double bleed_reduction) {
  const double mu = moments.x;
  if (receiver_depth <= mu) return 1.0;
  const double sigma2 = std::max(moments.y - mu * mu, min_variance);
  const double t = receiver_depth - mu;
  return reduce_light_bleeding_reference(sigma2 / (sigma2 + t * t), bleed_reduction);
}

double esm_reference(double filtered, double receiver_depth, double c) {
  // In double, exp(c) for c <= 87 is far from overflow: evaluate directly.
  const double occluder = std::max(filtered, std::exp(-c));
  return std::min(1.0, occluder * std::exp(-c * (receiver_depth - 1.0)));
}

glm::dvec2 evsm_warp_reference(double z, double positive_exponent, double negative_exponent) {
  const double u = 2.0 * z - 1.0;
  return {std::exp(positive_exponent * u), -std::exp(-negative_exponent * u)};
}

double evsm_reference(glm::dvec4 m, double z, double positive_exponent, double negative_exponent,
                      double min_variance, bool four) {
  const glm::dvec2 w = evsm_warp_reference(z, positive_exponent, negative_exponent);
  auto bound = [&](double mean, double second, double receiver, double exponent) {
    if (receiver <= mean) return 1.0;
    const double slope = 2.0 * exponent * receiver;  // dw/dz, up to sign
    const double variance = std::max(second - mean * mean, slope * slope * min_variance);
    const double d = receiver - mean;
    return variance / (variance + d * d);
  };
  const double positive = bound(m.x, m.y, w.x, positive_exponent);
  return four ? std::min(positive, bound(m.z, m.w, w.y, negative_exponent)) : positive;
}

// Seed 002, matrix form, for moments b of u in [-1, 1]:
//   R = 3/2 b1 - 2 b3 + 1/2, G = 4 b2 - 4 b4,
//   B = sqrt(3)/2 b1 - sqrt(12)/9 b3 + 1/2, A = (b2 + b4) / 2.
glm::vec4 msm_quantize(glm::vec4 b) {
  const float sqrt3_2 = 0.8660254037844386f;
  const float sqrt12_9 = 0.3849001794597505f;
  const glm::vec4 q{1.5f * b.x - 2.0f * b.z + 0.5f, 4.0f * b.y - 4.0f * b.w,
                    sqrt3_2 * b.x - sqrt12_9 * b.z + 0.5f, 0.5f * b.y + 0.5f * b.w};
  return glm::clamp(q, 0.0f, 1.0f);
}

// The inverse (seed 002): b1 = -(R - 1/2) / 3 + sqrt(3) (B - 1/2),
// b2 = G / 8 + A, b3 = -3/4 (R - 1/2) + 3 sqrt(3) / 4 (B - 1/2), b4 = -G / 8 + A.
glm::vec4 msm_dequantize(glm::vec4 q) {
  const float r = q.x - 0.5f, g = q.y, bl = q.z - 0.5f, a = q.w;
  const float sqrt3 = 1.7320508075688772f;
  return {-r / 3.0f + sqrt3 * bl, 0.125f * g + a, -0.75f * r + 0.75f * sqrt3 * bl, -0.125f * g + a};
}

}  // namespace penumbra
