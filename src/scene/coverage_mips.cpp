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

// The smallest alpha byte that passes the test alpha >= cutoff.
int passing_byte(float cutoff) {
  int b = static_cast<int>(std::ceil(cutoff * 255.0f));
  while (b > 0 && static_cast<float>(b - 1) / 255.0f >= cutoff) --b;
  while (b < 256 && static_cast<float>(b) / 255.0f < cutoff) ++b;
  return b;
}

// Texels [lo, hi) of a source row or column that destination texel i of n
// averages: the whole source is covered, an odd side's last texel by the
// last destination texel.
std::pair<int, int> footprint(int i, int n, int source) {
  return {i * source / n, std::max(i * source / n + 1, (i + 1) * source / n)};
}

}  // namespace

double alpha_coverage(const MipLevel& level, float cutoff) {
  const int pass = passing_byte(cutoff);
  const std::size_t texels = level.rgba.size() / 4;
  if (texels == 0) return 0.0;
  std::size_t above = 0;
  for (std::size_t i = 0; i < texels; ++i) above += level.rgba[4 * i + 3] >= pass;
  return static_cast<double>(above) / static_cast<double>(texels);
}

std::vector<MipLevel> coverage_mip_chain(const TextureImage& image, float cutoff) {
  std::array<float, 256> linear{};
  for (int i = 0; i < 256; ++i) linear[i] = srgb_to_linear(static_cast<float>(i) / 255.0f);
  std::vector<MipLevel> chain;
  chain.push_back({image.width, image.height, image.rgba});
  const bool tested = cutoff > 0.0f && cutoff <= 1.0f;
  const double coverage = tested ? alpha_coverage(chain[0], cutoff) : 0.0;
  const int pass = tested ? passing_byte(cutoff) : 0;
  // Level k + 1 from level k: colour in linear light, alpha as a float mean
  // (moved about the cutoff and quantized below), both box-filtered.
  std::vector<float> colour, alpha;
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
    // Castaño's selection: the k texels of largest alpha, k = level 0's
    // coverage in texels of this level, pass and the others are holes.
    // Rather than scaling every alpha by the factor that puts the k-th on
    // the cutoff, each alpha moves only as far as it must (up to the
    // cutoff, or just under it), so that alpha far from the cutoff, an
    // opaque texel's 1 among them, is left as averaged (a vertex colour's
    // alpha multiplies it). Ties (common in the flat alpha of cut-outs)
    // are broken by a hash of the texel's index, so that the texels left
    // out of a tie are scattered, not the last rows.
    std::vector<bool> passes;
    if (tested) {
      const std::size_t keep = std::min(
          texels, static_cast<std::size_t>(std::lround(coverage * static_cast<double>(texels))));
      const auto hash = [](std::uint32_t i) {
        i ^= i >> 16;
        i *= 0x7feb352du;
        i ^= i >> 15;
        i *= 0x846ca68bu;
        return i ^ (i >> 16);
      };
      std::vector<std::uint32_t> order(texels);
      for (std::size_t i = 0; i < texels; ++i) order[i] = static_cast<std::uint32_t>(i);
      const auto before = [&](std::uint32_t a, std::uint32_t b) {
        return alpha[a] != alpha[b] ? alpha[a] > alpha[b] : hash(a) < hash(b);
      };
      passes.assign(texels, false);
      if (keep > 0) {
        std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep - 1),
                         order.end(), before);
        for (std::size_t i = 0; i < keep; ++i) passes[order[i]] = alpha[order[i]] > 0.0f;
      }
    }
    dst.rgba.resize(4 * texels);
    for (std::size_t i = 0; i < texels; ++i) {
      for (int c = 0; c < 3; ++c) dst.rgba[4 * i + c] = linear_to_srgb_byte(colour[3 * i + c]);
      int a = static_cast<int>(std::lround(std::clamp(alpha[i], 0.0f, 1.0f) * 255.0f));
      if (tested) a = passes[i] ? std::max(a, pass) : std::min(a, pass - 1);
      dst.rgba[4 * i + 3] = static_cast<std::uint8_t>(std::clamp(a, 0, 255));
    }
    chain.push_back(std::move(dst));
  }
  return chain;
}

float texture_alpha_cutoff(const Material& m) {
  const float cutoff = coverage_cutoff(m);
  if (cutoff <= 0.0f || !(m.alpha > 0.0f)) return -1.0f;
  const float t = cutoff / m.alpha;
  return t <= 1.0f ? t : -1.0f;
}

}  // namespace penumbra
