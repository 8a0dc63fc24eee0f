#include "scene/coverage_mips.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace penumbra {

namespace {

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::uint8_t linear_to_srgb_byte(double c) {
  c = std::clamp(c, 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(s * 255.0));
}

// Texels [lo, hi) of a source row or column that destination texel i of n
// averages: the whole source is covered, an odd side's last texel by the
// last destination texel.
std::pair<int, int> footprint(int i, int n, int source) {
  return {i * source / n, std::max(i * source / n + 1, (i + 1) * source / n)};
}

// The fraction of a w x h alpha image (bytes, one per texel) at or above
// the cutoff where a bilinear filter reads it (repeating at the edges): 4 x
// 4 points in each texel, of every `stride`-th texel row and column (so
// that a large level costs at most about a million reads).
double bilinear_coverage(const std::vector<std::uint8_t>& alpha, int w, int h, float cutoff) {
  if (alpha.empty()) return 0.0;
  const std::size_t texels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const int stride =
      std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(texels) / 65536.0))));
  const float threshold = cutoff * 255.0f;
  const auto at = [&](int x, int y) {
    x = (x % w + w) % w;
    y = (y % h + h) % h;
    return static_cast<float>(alpha[static_cast<std::size_t>(y) * w + x]);
  };
  long long above = 0, all = 0;
  for (int y = 0; y < h; y += stride) {
    for (int x = 0; x < w; x += stride) {
      for (int sy = 0; sy < 4; ++sy) {
        for (int sx = 0; sx < 4; ++sx) {
          // Texel centres at half-integers (OpenGL 4.5, section 8.14.2).
          const float px = static_cast<float>(x) + (static_cast<float>(sx) + 0.5f) / 4.0f - 0.5f;
          const float py = static_cast<float>(y) + (static_cast<float>(sy) + 0.5f) / 4.0f - 0.5f;
          const int x0 = static_cast<int>(std::floor(px)), y0 = static_cast<int>(std::floor(py));
          const float ax = px - static_cast<float>(x0), ay = py - static_cast<float>(y0);
          const float top = at(x0, y0) + ax * (at(x0 + 1, y0) - at(x0, y0));
          const float bottom = at(x0, y0 + 1) + ax * (at(x0 + 1, y0 + 1) - at(x0, y0 + 1));
          above += top + ay * (bottom - top) >= threshold;
          ++all;
        }
      }
    }
  }
  return static_cast<double>(above) / static_cast<double>(all);
}

std::vector<std::uint8_t> alpha_bytes(const MipLevel& level) {
  std::vector<std::uint8_t> a(level.rgba.size() / 4);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = level.rgba[4 * i + 3];
  return a;
}

// Alpha remapped so that `t` lands on the cutoff, 0 and 1 staying where
// they are (linear on either side of t), as bytes.
void remap(const std::vector<float>& alpha, float t, float cutoff, std::vector<std::uint8_t>& out) {
  out.resize(alpha.size());
  for (std::size_t i = 0; i < alpha.size(); ++i) {
    const float a = std::clamp(alpha[i], 0.0f, 1.0f);
    const float r = a < t ? cutoff * a / t : cutoff + (1.0f - cutoff) * (a - t) / (1.0f - t);
    out[i] = static_cast<std::uint8_t>(std::lround(std::clamp(r, 0.0f, 1.0f) * 255.0f));
  }
}

}  // namespace

double alpha_coverage(const MipLevel& level, float cutoff) {
  return bilinear_coverage(alpha_bytes(level), level.width, level.height, cutoff);
}

std::vector<MipLevel> coverage_mip_chain(const TextureImage& image, float cutoff) {
  std::array<float, 256> linear{};
  for (int i = 0; i < 256; ++i) linear[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
  std::vector<MipLevel> chain;
  chain.push_back({image.width, image.height, image.rgba});
  const bool tested = cutoff > 0.0f && cutoff < 1.0f;
  const double coverage = tested ? alpha_coverage(chain[0], cutoff) : 0.0;
  // Level k + 1 from level k: colour in linear light, alpha as a float mean
  // (remapped about the cutoff below), both box-filtered.
  std::vector<float> colour, alpha;
  std::vector<std::uint8_t> bytes;
  while (chain.back().width > 1 || chain.back().height > 1) {
    const MipLevel& src = chain.back();
    MipLevel dst{std::max(1, src.width / 2), std::max(1, src.height / 2), {}};
    const std::size_t texels = static_cast<std::size_t>(dst.width) * dst.height;
    colour.assign(3 * texels, 0.0f);
    alpha.assign(texels, 0.0f);
    for (int y = 0; y < dst.height; ++y) {
      const auto [y0, y1] = footprint(y, dst.height, src.height);
      for (int x = 0; x < dst.width; ++x) {
        const auto [x0, x1] = footprint(x, dst.width, src.width);
        std::array<double, 4> sum{};
        for (int sy = y0; sy < y1; ++sy) {
          for (int sx = x0; sx < x1; ++sx) {
            const std::uint8_t* p = &src.rgba[4 * (static_cast<std::size_t>(sy) * src.width + sx)];
            for (int c = 0; c < 3; ++c) sum[c] += linear[p[c]];
            sum[3] += p[3] / 255.0;
          }
        }
        const double n = static_cast<double>((y1 - y0) * (x1 - x0));
        const std::size_t i = static_cast<std::size_t>(y) * dst.width + x;
        for (int c = 0; c < 3; ++c) colour[3 * i + c] = static_cast<float>(sum[c] / n);
        alpha[i] = static_cast<float>(sum[3] / n);
      }
    }
    if (tested) {
      // Castaño's search: the alpha t that, moved onto the cutoff, gives
      // this level level 0's coverage as the bilinear filter reads it
      // (coverage falls as t rises). Castaño scales alpha by cutoff / t;
      // the remap below moves t alike but keeps 0 and 1 (an opaque texel
      // stays opaque, whatever vertex alpha multiplies it).
      float lo = 0.0f, hi = 1.0f;
      for (int step = 0; step < 16; ++step) {
        const float t = 0.5f * (lo + hi);
        remap(alpha, t, cutoff, bytes);
        (bilinear_coverage(bytes, dst.width, dst.height, cutoff) > coverage ? lo : hi) = t;
      }
      // Of the two sides of the last step (a jump, at small levels), the
      // one nearer level 0's coverage.
      remap(alpha, lo, cutoff, bytes);
      const double below = bilinear_coverage(bytes, dst.width, dst.height, cutoff);
      remap(alpha, hi, cutoff, bytes);
      const double above = bilinear_coverage(bytes, dst.width, dst.height, cutoff);
      if (std::abs(below - coverage) < std::abs(above - coverage)) remap(alpha, lo, cutoff, bytes);
    } else {
      bytes.resize(texels);
      for (std::size_t i = 0; i < texels; ++i) {
        bytes[i] =
            static_cast<std::uint8_t>(std::lround(std::clamp(alpha[i], 0.0f, 1.0f) * 255.0f));
      }
    }
    dst.rgba.resize(4 * texels);
    for (std::size_t i = 0; i < texels; ++i) {
      for (int c = 0; c < 3; ++c) dst.rgba[4 * i + c] = linear_to_srgb_byte(colour[3 * i + c]);
      dst.rgba[4 * i + 3] = bytes[i];
    }
    chain.push_back(std::move(dst));
  }
  return chain;
}

float texture_alpha_cutoff(const Material& m) {
  const float cutoff = coverage_cutoff(m);
  if (cutoff <= 0.0f || !(m.alpha > 0.0f)) return -1.0f;
  const float t = cutoff / m.alpha;
  return t < 1.0f ? t : -1.0f;
}

}  // namespace penumbra
