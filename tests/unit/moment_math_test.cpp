#include "penumbra/shadow/moment_math.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "penumbra/filter/gaussian.hpp"
#include "penumbra/settings.hpp"

namespace penumbra {
namespace {

// Moments (E[x], .., E[x^4]) of point masses `weights` at `depths` (in
// whatever depth variable x the caller uses).
glm::dvec4 moments_of(const std::vector<double>& depths, const std::vector<double>& weights) {
  glm::dvec4 b(0.0);
  for (std::size_t i = 0; i < depths.size(); ++i) {
    const double z = depths[i];
    b += weights[i] * glm::dvec4(z, z * z, z * z * z, z * z * z * z);
  }
  return b;
}

glm::dvec4 moments_of(double z) {
  return moments_of({z}, {1.0});
}

// The signed depth u = 2 z - 1 the MSM moments are of.
double signed_depth(double z) {
  return 2.0 * z - 1.0;
}

// The MSM moments (of u) of point masses `weights` at relative depths `depths`.
glm::dvec4 msm_moments_of(const std::vector<double>& depths, const std::vector<double>& weights) {
  glm::dvec4 b(0.0);
  for (std::size_t i = 0; i < depths.size(); ++i) b += weights[i] * msm_moments_of_depth(depths[i]);
  return b;
}

// --- Gaussian weights --------------------------------------------------------

TEST(GaussianWeights, ZeroWidthIsIdentity) {
  EXPECT_EQ(gaussian_weights(0), std::vector<float>{1.0f});
}

TEST(GaussianWeights, NormalizedSymmetricWithSigmaHalfWidth) {
  for (int w : {1, 2, 3, 5, 8, 16, 32}) {
    std::vector<float> weights = gaussian_weights(w);
    ASSERT_EQ(weights.size(), std::size_t(2 * w + 1));
    double sum = 0.0;
    for (float v : weights) sum += v;
    EXPECT_NEAR(sum, 1.0, 1e-6) << "w = " << w;
    const double s = w / 2.0;
    for (int i = 0; i <= w; ++i) {
      EXPECT_EQ(weights[w + i], weights[w - i]) << "w = " << w << ", i = " << i;
      EXPECT_NEAR(weights[w + i] / weights[w], std::exp(-i * i / (2.0 * s * s)), 1e-6)
          << "w = " << w << ", i = " << i;
    }
  }
}

// --- Hamburger 4MSM reference --------------------------------------------------

constexpr double kAlpha = 3e-5;

// A single occluder depth d (a point mass): with the bias, the moments are
// those of (1 - a) at d and a (0.1875, 0.625, 0.1875) at u = -1, 0, 1, so
// the sharp lower bound G is at most 0.8125 a in front of d and at least
// 1 - 0.8125 a - (a small amount) behind.
TEST(MsmReference, PointMassIsSharp) {
  double worst_front = 0.0, worst_behind = 0.0;
  for (double d : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const glm::dvec4 b = msm_moments_of_depth(d);
    for (double dz : {0.02, 0.05, 0.1, 0.3}) {
      if (d - dz >= 0.0) {
        const double g = msm_hamburger_reference(b, signed_depth(d - dz), kAlpha);
        worst_front = std::max(worst_front, g);
        EXPECT_LE(g, 1e-4) << "d = " << d << ", in front by " << dz;
      }
      if (d + dz <= 1.0) {
        const double g = msm_hamburger_reference(b, signed_depth(d + dz), kAlpha);
        worst_behind = std::max(worst_behind, 1.0 - g);
        EXPECT_GE(g, 1.0 - 2e-2) << "d = " << d << ", behind by " << dz;
        if (dz >= 0.1) {
          EXPECT_GE(g, 1.0 - 2e-3) << "d = " << d << ", behind by " << dz;
        }
      }
    }
  }
  std::printf("point mass, alpha = %g: max G in front %.3g, max 1 - G behind %.3g\n", kAlpha,
              worst_front, worst_behind);
}

// The sharp lower bound, computed a second way: the Hamburger G is the
// weight in front of z_f of the unique three-point distribution {x, z_f, y}
// (x < z_f < y) with moments (1, b') (Peters & Klein 2015). Solve
// for x and y by Newton's method on the two moment equations that the
// Vandermonde solve for the weights leaves over.
struct ThreePoint {
  double x, y, wx, wf, wy;
};

ThreePoint three_point_with_atom_at(const glm::dvec4& m, double z_f, double x, double y) {
  auto weights = [&](double a, double c) {
    // w_a + w_f + w_c = 1, sums of w z = m1 and of w z^2 = m2 (Cramer).
    const glm::dvec3 ca{1.0, a, a * a}, cf{1.0, z_f, z_f * z_f}, cc{1.0, c, c * c};
    const glm::dvec3 rhs{1.0, m.x, m.y};
    const double d = glm::determinant(glm::dmat3(ca, cf, cc));
    return glm::dvec3(glm::determinant(glm::dmat3(rhs, cf, cc)) / d,
                      glm::determinant(glm::dmat3(ca, rhs, cc)) / d,
                      glm::determinant(glm::dmat3(ca, cf, rhs)) / d);
  };
  auto residual = [&](double a, double c) {
    const glm::dvec3 w = weights(a, c);
    return glm::dvec2(w.x * a * a * a + w.y * z_f * z_f * z_f + w.z * c * c * c - m.z,
                      w.x * a * a * a * a + w.y * std::pow(z_f, 4) + w.z * c * c * c * c - m.w);
  };
  for (int iteration = 0; iteration < 100; ++iteration) {
    const glm::dvec2 r = residual(x, y);
    const double h = 1e-7;
    const glm::dmat2 jacobian((residual(x + h, y) - r) / h, (residual(x, y + h) - r) / h);
    const glm::dvec2 step = glm::inverse(jacobian) * r;
    x -= step.x;
    y -= step.y;
    if (glm::length(step) < 1e-14) break;
  }
  const glm::dvec3 w = weights(x, y);
  return {x, y, w.x, w.y, w.z};
}

// Two occluder depths d1 < d2 with half the mass each: behind both, G ~ 1;
// in front of both, G ~ 0. Strictly between them, the only distribution
// with these unbiased moments is the two atoms themselves, so as alpha -> 0
// the sharp lower bound is the mass of d1, G -> 1/2. With the bias it is the
// front weight of the three-point distribution above, below 1/2 (a lower
// bound on the biased distribution's own front mass, which is exactly 1/2)
// by an amount proportional to alpha.
TEST(MsmReference, TwoDepthsHalfAndHalf) {
  double worst_between = 0.0, worst_vs_three_point = 0.0;
  const double pairs[][2] = {{0.2, 0.6}, {0.3, 0.5}, {0.1, 0.9}, {0.4, 0.8}};
  for (const auto& pair : pairs) {
    // In the signed depth the moments are of.
    const double d1 = signed_depth(pair[0]), d2 = signed_depth(pair[1]);
    const glm::dvec4 b = moments_of({d1, d2}, {0.5, 0.5});
    EXPECT_LE(msm_hamburger_reference(b, d1 - 0.1, kAlpha), 1e-4);
    EXPECT_GE(msm_hamburger_reference(b, d2 + 0.2, kAlpha), 1.0 - 5e-3);
    for (double t : {0.25, 0.5, 0.75}) {
      const double z_f = d1 + t * (d2 - d1);
      const double g = msm_hamburger_reference(b, z_f, kAlpha);
      const glm::dvec4 biased = (1.0 - kAlpha) * b + kAlpha * kMsmBias32;
      const ThreePoint p = three_point_with_atom_at(biased, z_f, d1, d2);
      ASSERT_LT(p.x, z_f);
      ASSERT_GT(p.y, z_f);
      ASSERT_GE(std::min({p.wx, p.wf, p.wy}), 0.0);
      EXPECT_NEAR(g, p.wx, 1e-8) << d1 << ", " << d2 << ", z_f = " << z_f;
      worst_vs_three_point = std::max(worst_vs_three_point, std::abs(g - p.wx));
      EXPECT_LE(g, 0.5);
      EXPECT_NEAR(g, 0.5, 0.05) << d1 << ", " << d2 << ", z_f = " << z_f;
      worst_between = std::max(worst_between, 0.5 - g);
      // Linear in alpha to first order: a 1000 times smaller bias, a gap about
      // 1000 times smaller (within 10%: the second-order term).
      const double g_small = msm_hamburger_reference(b, z_f, kAlpha * 1e-3);
      EXPECT_NEAR((0.5 - g_small) * 1e3, 0.5 - g, 0.1 * (0.5 - g) + 1e-9);
    }
  }
  std::printf(
      "two depths, alpha = %g: max 0.5 - G between them %.3g; "
      "|G - three-point front weight| %.3g\n",
      kAlpha, worst_between, worst_vs_three_point);
}

// n random depths in [0, 1) with random weights summing to 1.
void random_mixture(std::mt19937& rng, int n, std::vector<double>& depths,
                    std::vector<double>& weights) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  depths.resize(static_cast<std::size_t>(n));
  weights.resize(static_cast<std::size_t>(n));
  double total = 0.0;
  for (std::size_t i = 0; i < depths.size(); ++i) {
    depths[i] = u01(rng);
    weights[i] = 0.05 + u01(rng);
    total += weights[i];
  }
  for (double& w : weights) w /= total;
}

// G is monotone in the receiver depth and stays in [0, 1] for random
// mixtures of up to four depths, with both bias vectors.
TEST(MsmReference, MonotoneInReceiverDepth) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 4;
    std::vector<double> depths, weights;
    random_mixture(rng, n, depths, weights);
    const glm::dvec4 b = msm_moments_of(depths, weights);
    for (const glm::dvec4& bias : {kMsmBias32, kMsmBias16}) {
      double previous = 0.0;
      for (int k = 0; k <= 100; ++k) {
        const double g = msm_hamburger_reference(b, signed_depth(k / 100.0), kAlpha, bias);
        ASSERT_GE(g, previous - 1e-9) << "trial " << trial << ", z_f = " << k / 100.0;
        ASSERT_LE(g, 1.0);
        previous = g;
      }
    }
  }
}

// --- Bias vectors --------------------------------------------------------------

TEST(MsmBias, BiasVectorsArePetersDistributions) {
  // 32-bit, (0, 0.375, 0, 0.375): 0.1875 at u = -1 and 1, 0.625 at 0.
  const glm::dvec4 b32 = moments_of({-1.0, 0.0, 1.0}, {0.1875, 0.625, 0.1875});
  // 16-bit, (0, 0.628, 0, 0.628): 0.314 at -1 and 1, 0.372 at 0.
  const glm::dvec4 b16 = moments_of({-1.0, 0.0, 1.0}, {0.314, 0.372, 0.314});
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(kMsmBias32[k], b32[k], 1e-15);
    EXPECT_NEAR(kMsmBias16[k], b16[k], 1e-15);
  }
}

TEST(MsmBias, ConversionFromSignedDepthIsTheBinomialExpansion) {
  for (double z : {0.0, 0.2, 0.5, 0.625, 1.0}) {
    const glm::dvec4 converted = msm_moments_from_signed(msm_moments_of_depth(z));
    const glm::dvec4 direct = moments_of(z);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(converted[k], direct[k], 1e-15);
  }
}

// The Hamburger bound does not depend on the depth variable: solving the
// moments of u = 2 z - 1 against u_f gives, in exact arithmetic, what
// solving the moments of z against z_f does, with the bias distribution
// mapped along. (So storing u changes only the rounding, which is the point.)
TEST(MsmReference, SignedDepthSolveEqualsUnitDepthSolve) {
  std::mt19937 rng(2017);
  double worst = 0.0;
  for (int trial = 0; trial < 500; ++trial) {
    const int n = 1 + trial % 4;
    std::vector<double> depths, weights;
    random_mixture(rng, n, depths, weights);
    const glm::dvec4 signed_moments = msm_moments_of(depths, weights);
    const glm::dvec4 unit_moments = moments_of(depths, weights);
    for (const glm::dvec4& bias : {kMsmBias32, kMsmBias16}) {
      for (double z_f : {0.1, 0.35, 0.5, 0.8, 0.97}) {
        const double g_signed =
            msm_hamburger_reference(signed_moments, signed_depth(z_f), kAlpha, bias);
        const double g_unit =
            msm_hamburger_reference(unit_moments, z_f, kAlpha, msm_moments_from_signed(bias));
        worst = std::max(worst, std::abs(g_signed - g_unit));
        EXPECT_NEAR(g_signed, g_unit, 1e-6) << "trial " << trial << ", z_f = " << z_f;
      }
    }
  }
  std::printf("Hamburger bound on u vs on z (double): max |dG| %.3g\n", worst);
}

// Why the moments are of u: near the far end of the depth range, float32
// moments of z keep too little of a filtered edge. A receiver surface at
// depth r, 5e-4 to 5e-3 behind an occluder at d in [0.97, 0.999] that
// covers a fraction w of its filter region: the texels' moments are
// computed and mixed in float as the resolve and the filter do, then solved
// in double (so only the storage differs), against the same solve of the
// exact mixture. With moments of z many shadows are off by more than 0.05;
// with moments of u, at the default alpha, none.
TEST(MsmPrecision, SignedDepthMomentsKeepNearFarEdgesInFloat) {
  const double alpha = ShadowSettings{}.msm_alpha;
  // The old convention's bias and alpha: half the mass at z = 0 and 1, 1e-5.
  const glm::dvec4 unit_bias = msm_moments_from_signed({0.0, 1.0, 0.0, 1.0});
  const double unit_alpha = 1e-5;
  auto float_moments = [](float x) {
    const float x2 = x * x;
    return glm::vec4(x, x2, x2 * x, x2 * x2);
  };
  auto double_moments = [](double x) { return moments_of(x); };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const int count = 20000;
  int off_unit = 0, off_signed = 0;
  double worst_unit = 0.0, worst_signed = 0.0;
  for (int i = 0; i < count; ++i) {
    float d, r;
    do {  // both depths in the map's range [0, 1]
      d = static_cast<float>(0.97 + 0.029 * u01(rng));
      r = static_cast<float>(d + 5e-4 * std::pow(10.0, u01(rng)));
    } while (r > 1.0f);
    const float w = static_cast<float>(u01(rng));
    // Moments of z.
    const glm::vec4 unit = w * float_moments(d) + (1.0f - w) * float_moments(r);
    const glm::dvec4 unit_exact = double(w) * double_moments(d) + (1.0 - w) * double_moments(r);
    const double e_unit =
        std::abs(msm_hamburger_reference(glm::dvec4(unit), r, unit_alpha, unit_bias) -
                 msm_hamburger_reference(unit_exact, r, unit_alpha, unit_bias));
    // Moments of u (2 z - 1 is exact in float here).
    const float ud = 2.0f * d - 1.0f, ur = 2.0f * r - 1.0f;
    const glm::vec4 sgn = w * float_moments(ud) + (1.0f - w) * float_moments(ur);
    const glm::dvec4 sgn_exact = double(w) * double_moments(ud) + (1.0 - w) * double_moments(ur);
    const double e_signed = std::abs(msm_hamburger_reference(glm::dvec4(sgn), ur, alpha) -
                                     msm_hamburger_reference(sgn_exact, ur, alpha));
    off_unit += e_unit > 0.05;
    off_signed += e_signed > 0.05;
    worst_unit = std::max(worst_unit, e_unit);
    worst_signed = std::max(worst_signed, e_signed);
  }
  std::printf(
      "near-far edges in float32 storage: moments of z off by > 0.05 in %.2f%% (max %.3f); "
      "moments of u (alpha %g) in %.2f%% (max %.3f)\n",
      100.0 * off_unit / count, worst_unit, alpha, 100.0 * off_signed / count, worst_signed);
  EXPECT_GT(off_unit, count / 100);
  EXPECT_EQ(off_signed, 0);
}

// --- 16-bit quantization --------------------------------------------------------

// Seed 002's matrix form (rows R, G, B, A acting on (u1, u2, u3, u4)) and
// the inverse it prints; glm is column-major, so build from rows.
glm::dmat4 from_rows(const double r[4][4]) {
  glm::dmat4 m;
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) m[col][row] = r[row][col];
  }
  return m;
}

TEST(MsmQuantize, SeedInverseMatchesTheMatrixForm) {
  const double s3 = std::sqrt(3.0);
  const double forward[4][4] = {{1.5, 0.0, -2.0, 0.0},
                                {0.0, 4.0, 0.0, -4.0},
                                {s3 / 2.0, 0.0, -std::sqrt(12.0) / 9.0, 0.0},
                                {0.0, 0.5, 0.0, 0.5}};
  const double printed_inverse[4][4] = {{-1.0 / 3.0, 0.0, s3, 0.0},
                                        {0.0, 0.125, 0.0, 1.0},
                                        {-0.75, 0.0, 0.75 * s3, 0.0},
                                        {0.0, -0.125, 0.0, 1.0}};
  const glm::dmat4 inverse = glm::inverse(from_rows(forward));
  const glm::dmat4 printed = from_rows(printed_inverse);
  double max_diff = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      max_diff = std::max(max_diff, std::abs(inverse[c][r] - printed[c][r]));
    }
  }
  EXPECT_LT(max_diff, 1e-14);
  // The seed's text form flips the signs of R's z and z^3 terms
  // (-3/2 z + 2 z^3 + 1/2): the printed inverse does not invert that one.
  double text_form[4][4];
  std::copy(&forward[0][0], &forward[0][0] + 16, &text_form[0][0]);
  text_form[0][0] = -1.5;
  text_form[0][2] = 2.0;
  const glm::dmat4 product = printed * from_rows(text_form);
  double text_error = 0.0;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      text_error = std::max(text_error, std::abs(product[c][r] - (c == r ? 1.0 : 0.0)));
    }
  }
  EXPECT_GT(text_error, 0.5);
  std::printf(
      "seed 002 inverse vs double inverse of the matrix form: %.3g; of the text form: %.3g\n",
      max_diff, text_error);
}

std::vector<glm::dvec4> random_moment_vectors(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<glm::dvec4> result;
  for (double z : {0.0, 1e-3, 0.25, 0.5, 0.75, 0.999, 1.0}) {
    result.push_back(msm_moments_of_depth(z));
  }
  for (int trial = 0; trial < count; ++trial) {
    const int n = 1 + trial % 4;
    std::vector<double> depths(n), weights(n);
    double total = 0.0;
    for (int i = 0; i < n; ++i) {
      depths[i] = u01(rng);
      weights[i] = u01(rng) + 1e-3;
      total += weights[i];
    }
    for (double& w : weights) w /= total;
    result.push_back(msm_moments_of(depths, weights));
  }
  return result;
}

TEST(MsmQuantize, RoundTripsThroughSixteenBits) {
  double max_exact = 0.0, max_16 = 0.0;
  float lo = 1.0f, hi = 0.0f;
  for (const glm::dvec4& b : random_moment_vectors(10000, 11)) {
    const glm::vec4 bf(b);
    const glm::vec4 q = msm_quantize(bf);
    for (int k = 0; k < 4; ++k) {
      lo = std::min(lo, q[k]);
      hi = std::max(hi, q[k]);
      ASSERT_GE(q[k], 0.0f);
      ASSERT_LE(q[k], 1.0f);
    }
    const glm::vec4 back = msm_dequantize(q);
    const glm::vec4 q16 = glm::round(q * 65535.0f) / 65535.0f;
    const glm::vec4 back16 = msm_dequantize(q16);
    for (int k = 0; k < 4; ++k) {
      max_exact = std::max(max_exact, std::abs(double(back[k]) - b[k]));
      max_16 = std::max(max_16, std::abs(double(back16[k]) - b[k]));
    }
  }
  std::printf(
      "msm16 round trip: max error %.3g in float, %.3g through 16-bit UNORM; "
      "quantized range [%.4f, %.4f]\n",
      max_exact, max_16, lo, hi);
  EXPECT_LE(max_exact, 1e-6);
  EXPECT_LE(max_16, 1e-4);
}

// A point mass anywhere in [0, 1] reaches the ends of the UNORM range: the
// transform uses the whole of it (R = 0 at z = 0.25 and 1, R = 1 at 0 and 0.75).
TEST(MsmQuantize, PointMassesSpanTheUnitRange) {
  const glm::vec4 at0 = msm_quantize(glm::vec4(msm_moments_of_depth(0.0)));
  const glm::vec4 at1 = msm_quantize(glm::vec4(msm_moments_of_depth(1.0)));
  const glm::vec4 mid = msm_quantize(glm::vec4(msm_moments_of_depth(0.5)));
  EXPECT_NEAR(at0.x, 1.0f, 1e-6f);
  EXPECT_NEAR(at1.x, 0.0f, 1e-6f);
  EXPECT_NEAR(mid.x, 0.5f, 1e-6f);
  EXPECT_NEAR(mid.y, 0.0f, 1e-6f);
  EXPECT_NEAR(at1.w, 1.0f, 1e-6f);
}

// --- VSM, ESM ---------------------------------------------------------------------

TEST(VsmReference, ChebyshevBound) {
  const glm::dvec2 m{0.4, 0.4 * 0.4 + 0.01};  // variance 0.01
  EXPECT_EQ(vsm_reference(m, 0.3, 1e-4, 0.0), 1.0);
  EXPECT_EQ(vsm_reference(m, 0.4, 1e-4, 0.0), 1.0);
  EXPECT_NEAR(vsm_reference(m, 0.5, 1e-4, 0.0), 0.01 / (0.01 + 0.01), 1e-12);
  EXPECT_NEAR(vsm_reference(m, 0.5, 1e-4, 0.2), (0.5 - 0.2) / 0.8, 1e-12);
  // A flat occluder: the minimum variance takes over.
  EXPECT_NEAR(vsm_reference({0.4, 0.16}, 0.41, 1e-4, 0.0), 1e-4 / (1e-4 + 1e-4), 1e-9);
}

TEST(EsmReference, ShiftedEncodingMatchesTheSeedFormula) {
  for (double c : {1.0, 40.0, 60.0, 87.0}) {
    for (double z : {0.0, 0.3, 0.7, 1.0}) {
      const double filtered = std::exp(c * (z - 1.0));
      for (double z_f : {0.0, 0.2, 0.5, 0.71, 1.0}) {
        const double seed = std::min(1.0, std::exp(c * z) * std::exp(-c * z_f));
        EXPECT_NEAR(esm_reference(filtered, z_f, c), seed, 1e-12 * std::max(seed, 1e-300))
            << "c = " << c << ", z = " << z << ", z_f = " << z_f;
      }
    }
    // Below the encoding of depth 0 reads as an occluder at depth 0.
    EXPECT_NEAR(esm_reference(0.0, 0.0, c), 1.0, 1e-12);
    EXPECT_NEAR(esm_reference(0.0, 1.0, c), std::exp(-c), 1e-12 * std::exp(-c));
  }
}

}  // namespace
}  // namespace penumbra
