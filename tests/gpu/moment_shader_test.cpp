// The shadow-factor includes (shaders/shadow/{msm,vsm,esm,bleeding}.glsl),
// run on the GPU through shaders/test/shadow_math.comp, against the
// double-precision references of src/shadow/moment_math.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>
#include <vector>

#include "gpu_fixture.hpp"
#include "penumbra/gl/program.hpp"
#include "penumbra/gl/resources.hpp"
#include "penumbra/settings.hpp"
#include "penumbra/shadow/moment_math.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;
using testing::shared_context;

// Mirrors shaders/test/shadow_math.comp.
enum Mode : int {
  kMsm = 0,
  kVsm = 1,
  kEsm = 2,
  kQuantize = 3,
  kDequantize = 4,
  kBleeding = 5,
  kMsmMix = 6,
  kMsm16Mix = 7,
  kMsmBlocker = 8,
  kEvsm = 9
};

struct Case {
  glm::vec4 a{0.0f};
  glm::vec4 b{0.0f};
  glm::vec4 c{0.0f};
};
static_assert(sizeof(Case) == 48);

std::vector<glm::vec4> run_kernel(Mode mode, const std::vector<Case>& cases) {
  shared_context();
  static gl::Program program = gl::Program::compute("test/shadow_math.comp");
  gl::Buffer input = gl::Buffer::from(std::span<const Case>(cases), "shadow math cases");
  gl::Buffer output(cases.size() * sizeof(glm::vec4), nullptr, false, "shadow math results");
  program.use();
  glProgramUniform1i(program.id(), 0, mode);
  glProgramUniform1ui(program.id(), 1, static_cast<GLuint>(cases.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
  glDispatchCompute(static_cast<GLuint>((cases.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> results(cases.size());
  glGetNamedBufferSubData(output.id(), 0, static_cast<GLsizeiptr>(output.size()), results.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  return results;
}

bool finite(const glm::vec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

glm::dvec4 moments_of(double x) {
  return {x, x * x, x * x * x, x * x * x * x};
}

// MSM moments (of u = 2 z - 1) of a random mixture of 1-4 relative depths
// in [0, 1] with random weights.
glm::dvec4 random_moments(std::mt19937& rng) {
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const int n = std::uniform_int_distribution<int>(1, 4)(rng);
  glm::dvec4 b(0.0);
  double total = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w = u01(rng) + 1e-3;
    b += w * msm_moments_of_depth(u01(rng));
    total += w;
  }
  return b / total;
}

constexpr int kCount = 10000;

// 10,000 random moment vectors and receivers: the shader (float, Cholesky)
// against the reference (double, Cramer's rule) on the same float inputs.
TEST_F(GpuTest, MsmHamburgerMatchesDoubleReference) {
  std::mt19937 rng(2015);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const double alpha32 = 3e-5, alpha16 = 6e-5;
  // Another valid bias: 0.3 at u = -0.6, 0.4 at 0.2, 0.3 at 0.9.
  const glm::vec4 custom_bias(0.3 * moments_of(-0.6) + 0.4 * moments_of(0.2) +
                              0.3 * moments_of(0.9));
  std::vector<Case> cases(kCount);
  for (Case& k : cases) {
    k.a = glm::vec4(random_moments(rng));
    k.b = glm::vec4(float(2.0 * u01(rng) - 1.0), float(alpha32), 0.0f, 0.0f);
    k.c = custom_bias;
  }
  // Second half: the 16-bit path's alpha on the same kind of input.
  for (std::size_t i = kCount / 2; i < cases.size(); ++i) cases[i].b.y = float(alpha16);
  const std::vector<glm::vec4> gpu = run_kernel(kMsm, cases);

  // The reference's own spread when each input moment moves by 2 float
  // ulps: the error that storing these moments as float32 already makes.
  auto input_sensitivity = [](const glm::dvec4& b, double z_f, double alpha, const glm::dvec4& bias,
                              double g) {
    double spread = 0.0;
    for (int k = 0; k < 4; ++k) {
      for (double e : {-2.4e-7, 2.4e-7}) {
        glm::dvec4 perturbed = b;
        perturbed[k] *= 1.0 + e;
        spread =
            std::max(spread, std::abs(msm_hamburger_reference(perturbed, z_f, alpha, bias) - g));
      }
    }
    return spread;
  };
  const char* names[] = {"32-bit bias", "16-bit bias", "custom bias"};
  const glm::dvec4 biases[] = {kMsmBias32, kMsmBias16, glm::dvec4(custom_bias)};
  for (int column = 0; column < 3; ++column) {
    std::vector<double> errors;
    double max_error = 0.0, max_excess = 0.0, max_sensitivity = 0.0;
    int ill_conditioned = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      ASSERT_TRUE(finite(gpu[i])) << i;
      const glm::dvec4 b(cases[i].a);
      const double z_f = cases[i].b.x, alpha = cases[i].b.y;
      const double g = msm_hamburger_reference(b, z_f, alpha, biases[column]);
      const double error = std::abs(gpu[i][column] - g);
      errors.push_back(error);
      max_error = std::max(max_error, error);
      if (error > 1e-4) {
        const double sensitivity = input_sensitivity(b, z_f, alpha, biases[column], g);
        max_sensitivity = std::max(max_sensitivity, sensitivity);
        ill_conditioned += sensitivity > 1e-3;
        max_excess = std::max(max_excess, error - sensitivity);
      }
    }
    std::sort(errors.begin(), errors.end());
    const double p99 = errors[errors.size() * 99 / 100], p999 = errors[errors.size() * 999 / 1000];
    std::printf(
        "msm_hamburger, %s, %d cases: |dG| 99%% <= %.2g, 99.9%% <= %.2g, max %.3g; "
        "beyond the float32 input spread by at most %.2g (%d cases with a spread > 1e-3, "
        "up to %.2g)\n",
        names[column], kCount, p99, p999, max_error, max_excess, ill_conditioned, max_sensitivity);
    EXPECT_LE(p99, 1e-3) << names[column];
    EXPECT_LE(max_excess, 1e-3) << names[column];
    EXPECT_LE(max_error, 5e-2) << names[column];
  }
}

// Degenerate input: finite G in [0, 1], and the sensible answer where
// there is one.
TEST_F(GpuTest, MsmHamburgerIsFiniteOnDegenerateInput) {
  // Moments of u = 2 z - 1 in [-1, 1].
  const std::vector<glm::vec4> moments = {
      glm::vec4(-1.0f, 1.0f, -1.0f, 1.0f),    // constant depth u = -1 (z = 0)
      glm::vec4(1.0f),                        // constant depth u = 1 (z = 1)
      glm::vec4(0.0f),                        // constant depth u = 0
      glm::vec4(moments_of(-0.4)),            //
      glm::vec4(0.5f, 0.2f, 0.1f, 0.05f),     // negative variance: no distribution
      glm::vec4(0.0f, 1.0f, 0.0f, 1.0f),      // half at -1, half at 1 (two atoms)
      glm::vec4(0.0f, 0.375f, 0.0f, 0.375f),  // the 32-bit bias itself
      glm::vec4(0.5f, 0.25f, 0.0f, 1.0f),     // not a moment vector
  };
  const float receivers[] = {-1.5f, -1.0f, -0.4f, 0.0f, 0.5f, 1.0f, 1.5f};
  const float alphas[] = {0.0f, 1e-7f, 3e-5f, 1e-3f};
  std::vector<Case> cases;
  for (const glm::vec4& b : moments) {
    for (float z_f : receivers) {
      for (float alpha : alphas) {
        cases.push_back({b, glm::vec4(z_f, alpha, 0.0f, 0.0f), glm::vec4(0.5f)});
      }
    }
  }
  const std::vector<glm::vec4> gpu = run_kernel(kMsm, cases);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const glm::vec4& b = cases[i].a;
    const float z_f = cases[i].b.x, alpha = cases[i].b.y;
    ASSERT_TRUE(finite(gpu[i])) << "b = " << b.x << "," << b.y << "," << b.z << "," << b.w
                                << " z_f = " << z_f << " alpha = " << alpha;
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(gpu[i][k], 0.0f);
      EXPECT_LE(gpu[i][k], 1.0f);
    }
    // A single occluder depth d (the first four rows): the receiver 0.4 or
    // more in front (0.2 in z) is lit, 0.4 or more behind is shadowed.
    const std::size_t row = i / (std::size(receivers) * std::size(alphas));
    if (row < 4 && alpha > 0.0f) {
      const float d = b.x;
      for (int k = 0; k < 2; ++k) {
        if (z_f <= d - 0.4f) {
          EXPECT_LE(gpu[i][k], 1e-3f) << "d " << d << " z_f " << z_f;
        }
        if (z_f >= d + 0.4f) {
          EXPECT_GE(gpu[i][k], 1.0f - 1e-2f) << "d " << d << " z_f " << z_f;
        }
      }
    }
  }
}

// The blocker search of moment soft shadows (msm_blocker_search()) on the
// search region a receiver sees under a blocker: texels of the blocker at
// z_b, of the receiver's own surface at z_r, and of surfaces behind the
// receiver at z_k > z_r (the ground beyond a box, a slope falling away).
// The mean blocker depth is exactly z_b. Three depths are the quadrature's
// own kind of distribution, so Peters' estimate recovers z_b; the estimate
// that puts every unoccluded texel at the receiver's depth,
// (mean - (1 - G) z_f) / G, reads the texels behind as blockers pulled
// toward the receiver (computed here in double for comparison).
TEST_F(GpuTest, MsmBlockerSearchFindsTheMeanBlockerDepth) {
  std::mt19937 rng(2016);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * u01(rng); };
  constexpr double kAlpha = 1e-6;  // ShadowSettings' default msm_alpha
  struct Mixture {
    double z_b, z_f, occluded;
    glm::dvec4 b;
  };
  std::vector<Mixture> mixtures;
  std::vector<Case> cases;
  for (int i = 0; i < 2000; ++i) {
    Mixture m;
    m.z_b = uniform(0.05, 0.6);
    const double z_r = uniform(0.65, 0.85), z_k = z_r + uniform(0.05, 0.15);
    m.occluded = uniform(0.05, 0.9);
    const double w_r = (1.0 - m.occluded) * uniform(0.2, 0.8), w_k = 1.0 - m.occluded - w_r;
    m.z_f = z_r - 1e-3;  // the receiver, biased in front of its own surface
    m.b = m.occluded * msm_moments_of_depth(m.z_b) + w_r * msm_moments_of_depth(z_r) +
          w_k * msm_moments_of_depth(z_k);
    mixtures.push_back(m);
    cases.push_back({glm::vec4(m.b), glm::vec4(float(2.0 * m.z_f - 1.0), float(kAlpha), 0, 0),
                     glm::vec4(0.0f)});
  }
  const std::vector<glm::vec4> gpu = run_kernel(kMsmBlocker, cases);
  std::vector<double> errors, receiver_depth_errors;
  double worst_weight = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    ASSERT_TRUE(finite(gpu[i])) << i;
    const Mixture& m = mixtures[i];
    const double z_avg = 0.5 * (double(gpu[i].x) + 1.0);
    errors.push_back(std::abs(z_avg - m.z_b));
    worst_weight = std::max(worst_weight, std::abs(double(gpu[i].y) - m.occluded));
    const double g = msm_hamburger_reference(m.b, 2.0 * m.z_f - 1.0, kAlpha);
    const double mean = 0.5 * (m.b.x + 1.0);
    const double old = std::clamp((mean - (1.0 - g) * m.z_f) / g, 0.0, m.z_f);
    receiver_depth_errors.push_back(std::abs(old - m.z_b));
  }
  std::sort(errors.begin(), errors.end());
  std::sort(receiver_depth_errors.begin(), receiver_depth_errors.end());
  const std::size_t median = errors.size() / 2, p99 = errors.size() * 99 / 100;
  std::printf(
      "mean blocker depth |dz|: quadrature median %.2g, 99%% %.2g, max %.2g; unoccluded at the "
      "receiver's depth: median %.2g, 99%% %.2g, max %.2g; |dG| <= %.2g\n",
      errors[median], errors[p99], errors.back(), receiver_depth_errors[median],
      receiver_depth_errors[p99], receiver_depth_errors.back(), worst_weight);
  EXPECT_LE(errors[median], 0.003);
  EXPECT_LE(errors[p99], 0.02);
  EXPECT_LE(errors.back(), 0.05);
  // The blockers' weight is their fraction of the region.
  EXPECT_LE(worst_weight, 0.02);
}

// No blockers in front of the receiver: the estimate is the receiver's own
// depth (a zero-width penumbra) with no weight; a single blocker depth is
// found exactly.
TEST_F(GpuTest, MsmBlockerSearchOfOneOrNoBlocker) {
  const float u_f = 0.2f;
  std::vector<Case> cases = {
      // Everything behind the receiver: no blockers.
      {glm::vec4(0.5 * moments_of(0.5) + 0.5 * moments_of(0.9)), glm::vec4(u_f, 1e-6f, 0, 0),
       glm::vec4(0.0f)},
      // Everything at u = -0.6: all of it blocks, at -0.6.
      {glm::vec4(moments_of(-0.6)), glm::vec4(u_f, 1e-6f, 0, 0), glm::vec4(0.0f)},
  };
  const std::vector<glm::vec4> gpu = run_kernel(kMsmBlocker, cases);
  EXPECT_NEAR(gpu[0].x, u_f, 1e-3f);
  EXPECT_LE(gpu[0].y, 1e-3f);
  EXPECT_NEAR(gpu[1].x, -0.6f, 1e-3f);
  EXPECT_NEAR(gpu[1].y, 1.0f, 1e-3f);
}

TEST_F(GpuTest, MsmQuantizationMatchesCpuAndRoundTrips) {
  std::mt19937 rng(16);
  std::vector<Case> cases(kCount);
  for (Case& k : cases) k.a = glm::vec4(random_moments(rng));
  const std::vector<glm::vec4> quantized = run_kernel(kQuantize, cases);
  std::vector<Case> stored(kCount);
  double max_vs_cpu = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    ASSERT_TRUE(finite(quantized[i]));
    const glm::vec4 cpu = msm_quantize(cases[i].a);
    for (int k = 0; k < 4; ++k) {
      ASSERT_GE(quantized[i][k], 0.0f);
      ASSERT_LE(quantized[i][k], 1.0f);
      max_vs_cpu = std::max(max_vs_cpu, double(std::abs(quantized[i][k] - cpu[k])));
    }
    stored[i].a = glm::round(quantized[i] * 65535.0f) / 65535.0f;  // RGBA16 UNORM
  }
  const std::vector<glm::vec4> restored = run_kernel(kDequantize, stored);
  double max_round_trip = 0.0, max_dequantize_vs_cpu = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const glm::vec4 cpu = msm_dequantize(stored[i].a);
    for (int k = 0; k < 4; ++k) {
      max_round_trip = std::max(max_round_trip, double(std::abs(restored[i][k] - cases[i].a[k])));
      max_dequantize_vs_cpu =
          std::max(max_dequantize_vs_cpu, double(std::abs(restored[i][k] - cpu[k])));
    }
  }
  std::printf(
      "msm16 on GPU: quantize vs CPU %.3g, dequantize vs CPU %.3g, 16-bit round trip %.3g\n",
      max_vs_cpu, max_dequantize_vs_cpu, max_round_trip);
  EXPECT_LE(max_vs_cpu, 1e-5);
  EXPECT_LE(max_dequantize_vs_cpu, 1e-6);
  EXPECT_LE(max_round_trip, 1e-4);
}

// The whole 16-bit path on single occluder depths: quantize, round to
// RGBA16 UNORM, dequantize, solve with the 16-bit bias. A receiver 0.05 in
// front of the occluder (in z) must stay lit and one 0.1 behind it
// shadowed, for alpha in Peters' 16-bit range (a 32-bit-sized alpha is
// printed for comparison).
TEST_F(GpuTest, Msm16PathSeparatesLitFromShadowed) {
  std::vector<Case> cases;
  const float alphas[] = {3e-6f, 3e-5f, 6e-5f};
  for (float alpha : alphas) {
    for (int i = 0; i <= 200; ++i) {
      const double d = i / 200.0;
      const glm::vec4 q =
          glm::round(msm_quantize(glm::vec4(msm_moments_of_depth(d))) * 65535.0f) / 65535.0f;
      const glm::vec4 b = msm_dequantize(q);
      if (d >= 0.05) cases.push_back({b, glm::vec4(float(2.0 * d - 1.1), alpha, 1.0f, 0.0f), {}});
      if (d <= 0.9) cases.push_back({b, glm::vec4(float(2.0 * d - 0.8), alpha, 2.0f, 0.0f), {}});
    }
  }
  const std::vector<glm::vec4> gpu = run_kernel(kMsm, cases);
  for (float alpha : alphas) {
    double max_front = 0.0, max_behind = 0.0;  // G in front, 1 - G behind
    for (std::size_t i = 0; i < cases.size(); ++i) {
      if (cases[i].b.y != alpha) continue;
      ASSERT_TRUE(finite(gpu[i]));
      if (cases[i].b.z == 1.0f) max_front = std::max(max_front, double(gpu[i].y));
      if (cases[i].b.z == 2.0f) max_behind = std::max(max_behind, 1.0 - gpu[i].y);
    }
    std::printf("msm16 path, alpha = %g: max G 0.05 in front %.3g, max 1 - G 0.1 behind %.3g\n",
                alpha, max_front, max_behind);
    if (alpha >= 3e-5f) {
      EXPECT_LE(max_front, 1e-3) << "alpha " << alpha;
      EXPECT_LE(max_behind, 1e-2) << "alpha " << alpha;
    }
  }
}

// A receiver surface at relative depth r, 5e-4 to 5e-3 behind an occluder
// at d in [0.97, 0.999] that covers a fraction w of its filter region
// (a filtered shadow edge near the far end of the depth range, where
// floats are coarsest relative to the depth differences). The shader makes
// both texels' moments (msm_moments(), as the resolve does), mixes them in
// float (as the filter does) and solves; the double-precision solve of the
// exact mixture, with the same alpha and bias, is the target. With moments
// of z in [0, 1] stored in float32 (this code's first convention; same
// alpha, same bias distribution) 43% of these are off by more than 0.05,
// some by 1; with moments of u = 2 z - 1, none.
std::vector<Case> near_far_edges(int count) {
  std::mt19937 rng(97);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Case> cases(static_cast<std::size_t>(count));
  for (Case& k : cases) {
    float d, r;
    do {  // both depths in the map's range [0, 1]
      d = static_cast<float>(0.97 + 0.029 * u01(rng));
      r = static_cast<float>(d + 5e-4 * std::pow(10.0, u01(rng)));
    } while (r > 1.0f);
    k.a = glm::vec4(d, r, static_cast<float>(u01(rng)), r);  // the receiver on its surface
  }
  return cases;
}

TEST_F(GpuTest, MsmKeepsNearFarEdgesInFloat32) {
  const double alpha = ShadowSettings{}.msm_alpha;
  std::vector<Case> cases = near_far_edges(kCount);
  for (Case& k : cases) k.b.x = static_cast<float>(alpha);
  const std::vector<glm::vec4> gpu = run_kernel(kMsmMix, cases);
  int off = 0;
  double max_error = 0.0, max_vs_coverage = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const glm::vec4& a = cases[i].a;
    ASSERT_TRUE(finite(gpu[i])) << i;
    const double w = a.z;
    const glm::dvec4 exact = w * msm_moments_of_depth(a.x) + (1.0 - w) * msm_moments_of_depth(a.y);
    const double g = msm_hamburger_reference(exact, 2.0 * double(a.w) - 1.0, alpha, kMsmBias32);
    const double error = std::abs(gpu[i].x - g);
    off += error > 0.05;
    max_error = std::max(max_error, error);
    max_vs_coverage = std::max(max_vs_coverage, std::abs(gpu[i].x - w));
  }
  std::printf(
      "msm near-far edges (occluder at z 0.97-0.999, receiver 5e-4-5e-3 behind), alpha %g: "
      "%d of %d off the double solve by > 0.05, max %.3g (max |G - covered fraction| %.3g)\n",
      alpha, off, kCount, max_error, max_vs_coverage);
  EXPECT_EQ(off, 0);
  EXPECT_LE(max_error, 0.05);
}

// The same edges through msm16: two texels quantized and rounded to 16 bits
// (on the CPU, as an RGBA16 map stores them), mixed and solved in the
// shader, against the double solve of the same mixed 16-bit values
// dequantized in double: the float arithmetic after the 16-bit storage adds
// little. (Converting the dequantized moments back to moments of z, as this
// code once did, added up to 0.11 here, and over 0.01 in a quarter of the
// cases.)
glm::dvec4 dequantize_double(const glm::dvec4& q) {
  const double r = q.x - 0.5, g = q.y, b = q.z - 0.5, a = q.w, s3 = std::sqrt(3.0);
  return {-r / 3.0 + s3 * b, g / 8.0 + a, -0.75 * r + 0.75 * s3 * b, -g / 8.0 + a};
}

TEST_F(GpuTest, Msm16KeepsNearFarEdgesAfterDequantizing) {
  const double alpha = ShadowSettings{}.msm16_alpha;
  std::vector<Case> cases = near_far_edges(kCount);
  for (Case& k : cases) {
    const glm::vec4 depths = k.a;
    auto stored = [](float z) {
      return glm::round(msm_quantize(glm::vec4(msm_moments_of_depth(z))) * 65535.0f) / 65535.0f;
    };
    k.a = stored(depths.x);
    k.c = stored(depths.y);
    k.b = glm::vec4(depths.z, depths.w, static_cast<float>(alpha), 0.0f);
  }
  const std::vector<glm::vec4> gpu = run_kernel(kMsm16Mix, cases);
  int off = 0;
  double max_error = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& k = cases[i];
    ASSERT_TRUE(finite(gpu[i])) << i;
    const double w = k.b.x;
    const glm::dvec4 q = w * glm::dvec4(k.a) + (1.0 - w) * glm::dvec4(k.c);
    const double g =
        msm_hamburger_reference(dequantize_double(q), 2.0 * double(k.b.y) - 1.0, alpha, kMsmBias16);
    const double error = std::abs(gpu[i].x - g);
    off += error > 0.01;
    max_error = std::max(max_error, error);
  }
  std::printf(
      "msm16 near-far edges, alpha %g: %d of %d off the double solve of the same 16-bit values by "
      "> 0.01, max %.3g\n",
      alpha, off, kCount, max_error);
  EXPECT_LE(max_error, 0.01);
}

TEST_F(GpuTest, VsmMatchesDoubleReference) {
  std::mt19937 rng(2006);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Case> cases(kCount);
  const float bleeds[] = {0.0f, 0.2f, 0.5f};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const glm::dvec4 b = random_moments(rng);
    cases[i].a = glm::vec4(float(b.x), float(b.y), 0.0f, 0.0f);
    cases[i].b = glm::vec4(float(u01(rng)), i % 2 ? 1e-4f : 0.0f, bleeds[i % 3], 0.0f);
  }
  // Degenerate: zero variance with no floor, receiver on the mean.
  cases.push_back({glm::vec4(0.5f, 0.25f, 0.0f, 0.0f), glm::vec4(0.5f, 0.0f, 0.0f, 0.0f), {}});
  cases.push_back({glm::vec4(0.5f, 0.25f, 0.0f, 0.0f), glm::vec4(0.7f, 0.0f, 1.0f, 0.0f), {}});
  const std::vector<glm::vec4> gpu = run_kernel(kVsm, cases);
  // With no variance floor the bound is as ill-conditioned as M2 - M1^2;
  // the floor (1e-4 by default) is what makes VSM stable in float.
  double max_floored = 0.0, max_unfloored = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    ASSERT_TRUE(finite(gpu[i])) << i;
    const Case& k = cases[i];
    const double ref = vsm_reference(glm::dvec2(k.a.x, k.a.y), k.b.x, k.b.y, k.b.z);
    double& max_error = k.b.y > 0.0f ? max_floored : max_unfloored;
    max_error = std::max(max_error, std::abs(gpu[i].x - ref));
  }
  std::printf(
      "shadow_vsm vs double reference: max error %.3g with min variance 1e-4, "
      "%.3g with none\n",
      max_floored, max_unfloored);
  EXPECT_LE(max_floored, 5e-5);
  EXPECT_LE(max_unfloored, 1e-3);
}

TEST_F(GpuTest, LightBleedingReductionIsALinstep) {
  std::vector<Case> cases;
  for (float amount : {0.0f, 0.2f, 0.5f, 1.0f}) {
    for (float lit : {0.0f, 0.1f, 0.2f, 0.6f, 1.0f}) {
      cases.push_back({glm::vec4(0.0f), glm::vec4(lit, amount, 0.0f, 0.0f), {}});
    }
  }
  const std::vector<glm::vec4> gpu = run_kernel(kBleeding, cases);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const float lit = cases[i].b.x, amount = cases[i].b.y;
    EXPECT_NEAR(gpu[i].x, reduce_light_bleeding_reference(lit, amount), 1e-6)
        << "lit " << lit << " amount " << amount;
  }
}

TEST_F(GpuTest, EsmMatchesDoubleReferenceWithoutOverflow) {
  std::mt19937 rng(2008);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Case> cases;
  for (float c : {1.0f, 60.0f, 87.0f}) {
    for (float filtered : {0.0f, 1e-45f, 1e-38f, 1e-30f, 1.0f}) {
      for (float z_f : {-0.5f, 0.0f, 0.5f, 1.0f, 1.5f}) {
        cases.push_back({glm::vec4(0.0f), glm::vec4(filtered, z_f, c, 0.0f), {}});
      }
    }
    // Filtered maps: a random mixture of occluder depths.
    for (int i = 0; i < 1000; ++i) {
      double filtered = 0.0, total = 0.0;
      const int n = 1 + i % 4;
      for (int j = 0; j < n; ++j) {
        const double w = u01(rng) + 1e-3;
        filtered += w * std::exp(double(c) * (u01(rng) - 1.0));
        total += w;
      }
      cases.push_back(
          {glm::vec4(0.0f), glm::vec4(float(filtered / total), float(u01(rng)), c, 0.0f), {}});
    }
  }
  const std::vector<glm::vec4> gpu = run_kernel(kEsm, cases);
  double max_error = 0.0, max_encode_error = 0.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& k = cases[i];
    ASSERT_TRUE(finite(gpu[i])) << "filtered " << k.b.x << " z_f " << k.b.y << " c " << k.b.z;
    const double ref = esm_reference(k.b.x, k.b.y, k.b.z);
    max_error = std::max(max_error, std::abs(gpu[i].x - ref));
    // esm_encode of a receiver depth in [0, 1]: relative error.
    if (k.b.y >= 0.0f && k.b.y <= 1.0f) {
      const double encoded = std::exp(double(k.b.z) * (k.b.y - 1.0));
      max_encode_error = std::max(max_encode_error, std::abs(gpu[i].y / encoded - 1.0));
    }
  }
  std::printf(
      "shadow_esm vs double reference: max error %.3g; esm_encode max relative error %.3g\n",
      max_error, max_encode_error);
  EXPECT_LE(max_error, 1e-4);
  EXPECT_LE(max_encode_error, 1e-4);
}

// EVSM2 and EVSM4 (shaders/shadow/evsm.glsl) on two texels' warped moments
// mixed as a filter mixes them, against the double-precision formulas, at
// the default exponents and at the largest (42, where p^2 reaches e^84).
// Each is an upper bound of the true lit fraction (the weight of the texels
// at or behind the receiver), and evsm4's is the tighter.
TEST_F(GpuTest, EvsmMatchesDoubleReferenceAndBoundsTheLitFraction) {
  std::mt19937 rng(2008);
  std::uniform_real_distribution<float> u01(0.0f, 1.0f);
  std::vector<Case> cases;
  for (glm::vec2 c :
       {glm::vec2(40.0f, 5.0f), glm::vec2(kEvsmMaxExponent), glm::vec2(5.0f, 40.0f)}) {
    // Floors of a 2048^2 map's texel and of a few texels of a coarse one;
    // at c = 42 the first once overflowed the float floor (2 c w)^2.
    for (float min_variance : {1e-7f, 1e-5f, 1e-3f}) {
      for (int i = 0; i < 500; ++i) {
        const float d1 = u01(rng), d2 = u01(rng), w = u01(rng), z = u01(rng);
        cases.push_back({glm::vec4(d1, d2, w, z), glm::vec4(c, min_variance, 0.0f), {}});
      }
    }
  }
  const std::vector<glm::vec4> gpu = run_kernel(kEvsm, cases);
  double max_error2 = 0.0, max_error4 = 0.0;
  int tighter = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& k = cases[i];
    ASSERT_TRUE(finite(gpu[i])) << i;
    glm::dvec4 m(0.0);
    for (int t = 0; t < 2; ++t) {
      const double weight = t == 0 ? k.a.z : 1.0 - k.a.z;
      const glm::dvec2 w = evsm_warp_reference(t == 0 ? k.a.x : k.a.y, k.b.x, k.b.y);
      m += weight * glm::dvec4(w.x, w.x * w.x, w.y, w.y * w.y);
    }
    const double ref2 = evsm_reference(m, k.a.w, k.b.x, k.b.y, k.b.z, false);
    const double ref4 = evsm_reference(m, k.a.w, k.b.x, k.b.y, k.b.z, true);
    max_error2 = std::max(max_error2, std::abs(gpu[i].x - ref2));
    max_error4 = std::max(max_error4, std::abs(gpu[i].y - ref4));
    const double lit = (k.a.x >= k.a.w ? k.a.z : 0.0) + (k.a.y >= k.a.w ? 1.0 - k.a.z : 0.0);
    EXPECT_GE(ref2, lit - 1e-9) << i;  // Chebyshev: an upper bound
    EXPECT_GE(ref4, lit - 1e-9) << i;
    EXPECT_LE(gpu[i].y, gpu[i].x + 1e-6f) << i;
    tighter += ref4 < ref2 - 0.01 ? 1 : 0;
  }
  std::printf(
      "shadow_evsm2/4 vs double reference: max error %.3g / %.3g; evsm4 tighter in %d of "
      "%zu cases\n",
      max_error2, max_error4, tighter, cases.size());
  EXPECT_LE(max_error2, 1e-4);
  EXPECT_LE(max_error4, 1e-4);
  EXPECT_GT(tighter, 0);  // the negative warp matters somewhere
}

}  // namespace
}  // namespace penumbra
