#pragma once
// Float images read back from the GPU, and writing them as PNG or OpenEXR.
#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

// RGBA, 32-bit float, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0.0f) {}
  [[nodiscard]] float* pixel(int x, int y) {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
  [[nodiscard]] const float* pixel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
};

enum class PngEncoding {
  Srgb,    // linear colour: clamp to [0, 1], then the sRGB transfer curve
  Linear,  // data (shadow factor, depth, normals): clamp to [0, 1], no curve
};

enum class ImageFormat { Png, Exr };

// The format a path asks for by its extension (.png or .exr, any case).
// Throws UsageError for any other extension.
ImageFormat image_format_for(const std::string& path);

// Throws UsageError when the folder `path` would be written to does not
// exist or is not a writable folder; a device or FIFO `path` must itself be
// writable; "-" (standard output) always passes.
void check_output_path(const std::string& path);

// A PNG's 8-bit RGB pixels, rows top to bottom: an image's channels
// clamped to [0, 1] (not finite: 0), through the encoding's curve, rounded.
struct PngPixels {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};
PngPixels png_pixels(const Image& image, PngEncoding encoding);

// Writes atomically: to a temporary name beside the target, then renamed,
// so a failure never leaves a partial file. Throws RuntimeError.
void write_png(const Image& image, const std::string& path, PngEncoding encoding);
void write_png(const PngPixels& pixels, const std::string& path);
void write_exr(const Image& image, const std::string& path);
void write_image(const Image& image, const std::string& path, PngEncoding png_encoding);

// Reads a PNG as RGBA float in [0, 1] (no transfer curve applied).
Image read_png(const std::string& path);

}  // namespace penumbra
