#include "reference/light_sampling.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

namespace {

// A pseudo-random permutation of [0, l) chosen by p: a hash that is a
// bijection on the next power of two, cycle-walked until it lands below l
// (Kensler 2013, Listing 3).
std::uint32_t permute(std::uint32_t i, std::uint32_t l, std::uint32_t p) {
  std::uint32_t w = l - 1;
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  do {
    i ^= p;
    i *= 0xe170893du;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3fu;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1u | p >> 27;
    i *= 0x6935fa69u;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303u;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3u;
    i ^= (i & w) >> 2;
    i *= 0xc860a3dfu;
    i &= w;
    i ^= i >> 5;
  } while (i >= l);
  return (i + p) % l;
}

// A hash of (i, p) as a float in [0, 1) (Kensler 2013, Listing 4).
float randfloat(std::uint32_t i, std::uint32_t p) {
  i ^= p;
  i ^= i >> 17;
  i ^= i >> 10;
  i *= 0xb36534e5u;
  i ^= i >> 12;
  i ^= i >> 21;
  i *= 0x93fc4795u;
  i ^= 0xdf6e307fu;
  i ^= i >> 17;
  i *= 1u | p >> 18;
  return static_cast<float>(static_cast<double>(i) / 4294967808.0);
}

}  // namespace

glm::vec2 cmj_sample(std::uint32_t s, std::uint32_t n, std::uint32_t pattern) {
  // Kensler 2013, Listing 6: any n, aspect ratio 1.
  const auto m = static_cast<std::uint32_t>(std::sqrt(static_cast<double>(n)));
  const std::uint32_t rows = (n + m - 1) / m;
  s = permute(s, n, pattern * 0x51633e2du);
  const std::uint32_t sx = permute(s % m, m, pattern * 0x68bc21ebu);
  const std::uint32_t sy = permute(s / m, rows, pattern * 0x02e5be93u);
  const float jx = randfloat(s, pattern * 0x967a889bu);
  const float jy = randfloat(s, pattern * 0x368cc8b7u);
  const float x =
      (static_cast<float>(sx) + (static_cast<float>(sy) + jx) / static_cast<float>(rows)) /
      static_cast<float>(m);
  const float y = (static_cast<float>(s) + jy) / static_cast<float>(n);
  // Float rounding can reach 1 exactly; the square is half-open.
  return glm::min(glm::vec2(x, y), glm::vec2(1.0f - 0x1p-24f));
}

glm::vec2 concentric_disk(glm::vec2 u) {
  const glm::vec2 a = 2.0f * u - 1.0f;
  if (a.x == 0.0f && a.y == 0.0f) return glm::vec2(0.0f);
  const float quarter_pi = 0.78539816f;
  float r = 0.0f, phi = 0.0f;
  if (std::abs(a.x) > std::abs(a.y)) {
    r = a.x;
    phi = quarter_pi * (a.y / a.x);
  } else {
    r = a.y;
    phi = 2.0f * quarter_pi - quarter_pi * (a.x / a.y);
  }
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

glm::vec3 uniform_cone(glm::vec2 u, float one_minus_cos_max) {
  const glm::vec2 d = concentric_disk(u);
  const float r2 = glm::dot(d, d);
  if (r2 == 0.0f) return glm::vec3(0.0f, 0.0f, 1.0f);
  // 1 - cos(theta) and sin(theta) from it without cancellation:
  // sin^2 = (1 - cos)(1 + cos).
  const float one_minus_cos = r2 * one_minus_cos_max;
  const float cos_theta = 1.0f - one_minus_cos;
  const float sin_theta = std::sqrt(std::max(0.0f, one_minus_cos * (2.0f - one_minus_cos)));
  const glm::vec2 xy = d * (sin_theta / std::sqrt(r2));
  return glm::vec3(xy, cos_theta);
}

}  // namespace penumbra
