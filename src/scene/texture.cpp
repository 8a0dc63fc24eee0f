#include "scene/texture.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <vector>

#include <stb_image.h>

namespace penumbra {

namespace {

// Where a coordinate lands in [0, size) texels, with a wrap mode (OpenGL
// 4.5, section 8.14.2).
int wrap(int i, int size, TextureWrap mode) {
  switch (mode) {
    case TextureWrap::ClampToEdge:
      return std::clamp(i, 0, size - 1);
    case TextureWrap::MirroredRepeat: {
      const int period = 2 * size;
      int k = i % period;
      if (k < 0) k += period;
      return k < size ? k : period - 1 - k;
    }
    default: {
      const int k = i % size;
      return k < 0 ? k + size : k;
    }
  }
}

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

std::optional<TextureImage> decode_texture(const std::uint8_t* bytes, std::size_t size,
                                           const std::string& name, std::string& error) {
  if (size == 0 || size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    error = size == 0 ? "the file is empty" : "the file is too large";
    return std::nullopt;
  }
  int width = 0, height = 0, channels = 0;
  const int length = static_cast<int>(size);
  if (stbi_info_from_memory(bytes, length, &width, &height, &channels) == 0) {
    error = std::string("not a readable image (") + stbi_failure_reason() + ")";
    return std::nullopt;
  }
  if (width > kMaxTextureSide || height > kMaxTextureSide) {
    error = std::to_string(width) + "x" + std::to_string(height) + " is larger than " +
            std::to_string(kMaxTextureSide) + " texels a side";
    return std::nullopt;
  }
  stbi_uc* pixels = stbi_load_from_memory(bytes, length, &width, &height, &channels, 4);
  if (pixels == nullptr) {
    error = std::string("not a readable image (") + stbi_failure_reason() + ")";
    return std::nullopt;
  }
  TextureImage image;
  image.name = name;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels, pixels + std::size_t{4} * static_cast<std::size_t>(width) *
                                         static_cast<std::size_t>(height));
  stbi_image_free(pixels);
  return image;
}

std::optional<TextureImage> read_texture(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot be opened";
    return std::nullopt;
  }
  const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                        std::istreambuf_iterator<char>());
  return decode_texture(bytes.data(), bytes.size(), path, error);
}

glm::vec2 texture_coordinate(const Material& m, glm::vec2 uv) {
  return m.uv_transform * glm::vec3(uv, 1.0f);
}

glm::vec4 sample_texture(const Material& m, glm::vec2 t) {
  if (m.texture == nullptr || m.texture->width == 0) return glm::vec4(1.0f);
  const TextureImage& image = *m.texture;
  const auto texel = [&](int x, int y) {
    x = wrap(x, image.width, m.wrap_s);
    y = wrap(y, image.height, m.wrap_t);
    const std::uint8_t* p =
        &image.rgba[4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                         static_cast<std::size_t>(x))];
    return glm::vec4(srgb_to_linear(p[0] / 255.0f), srgb_to_linear(p[1] / 255.0f),
                     srgb_to_linear(p[2] / 255.0f), p[3] / 255.0f);
  };
  if (!std::isfinite(t.x) || !std::isfinite(t.y)) t = glm::vec2(0.0f);
  // Beyond a few periods the wrap is exact anyway; this keeps the texel
  // index within int.
  t = glm::clamp(t, glm::vec2(-1e6f), glm::vec2(1e6f));
  // Texel centres at half-integers, as OpenGL samples (section 8.14.2).
  const float x = t.x * static_cast<float>(image.width) - 0.5f;
  const float y = t.y * static_cast<float>(image.height) - 0.5f;
  if (m.nearest_magnification) {
    return texel(static_cast<int>(std::floor(x + 0.5f)), static_cast<int>(std::floor(y + 0.5f)));
  }
  const float fx = std::floor(x), fy = std::floor(y);
  const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
  const float ax = x - fx, ay = y - fy;
  return glm::mix(glm::mix(texel(x0, y0), texel(x0 + 1, y0), ax),
                  glm::mix(texel(x0, y0 + 1), texel(x0 + 1, y0 + 1), ax), ay);
}

glm::vec4 unpack_color(std::uint32_t rgba) {
  return glm::vec4(static_cast<float>(rgba & 0xffu), static_cast<float>((rgba >> 8) & 0xffu),
                   static_cast<float>((rgba >> 16) & 0xffu), static_cast<float>(rgba >> 24)) /
         255.0f;
}

std::uint32_t pack_color(const glm::vec4& rgba) {
  std::uint32_t out = 0;
  for (int i = 0; i < 4; ++i) {
    const float c = std::isfinite(rgba[i]) ? std::clamp(rgba[i], 0.0f, 1.0f) : 1.0f;
    out |= static_cast<std::uint32_t>(std::lround(c * 255.0f)) << (8 * i);
  }
  return out;
}

bool is_cut_out(const Material& m, float vertex_alpha, glm::vec2 uv) {
  const float cutoff = coverage_cutoff(m);
  if (cutoff < 0.0f) return false;
  const float alpha = m.alpha * vertex_alpha * sample_texture(m, texture_coordinate(m, uv)).a;
  return alpha < cutoff;
}

}  // namespace penumbra
