#include "io/image.hpp"

#include <tinyexr.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/display_name.hpp"
#include "io/atomic_file.hpp"
#include "penumbra/error.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

namespace penumbra {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

float srgb_encode(float linear) {
  linear = std::clamp(linear, 0.0f, 1.0f);
  return linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

// A value in [0, 1] to the byte lround(curve(v) * 255), for a curve that
// never falls (the sRGB transfer curve, or none), without evaluating it:
// from the smallest value that gives each byte, found once by bisection
// over the floats, and the byte at the start of each of 4096 equal
// intervals of [0, 1], from which a value climbs at most a byte or two.
class ByteQuantizer {
 public:
  template <class Curve>
  explicit ByteQuantizer(Curve curve) {
    const auto byte = [&](float v) { return std::lround(curve(v) * 255.0f); };
    for (int k = 1; k < 256; ++k) {
      // Floats in [0, 1] are ordered as their bit patterns.
      std::uint32_t low = 0, high = std::bit_cast<std::uint32_t>(1.0f);
      while (low < high) {
        const std::uint32_t mid = low + (high - low) / 2;
        if (byte(std::bit_cast<float>(mid)) >= k) {
          high = mid;
        } else {
          low = mid + 1;
        }
      }
      first_[k] = std::bit_cast<float>(low);
    }
    first_[0] = 0.0f;
    for (int i = 0; i < kIntervals; ++i) {
      interval_start_[i] = climb(0, static_cast<float>(i) / kIntervals);
    }
  }

  [[nodiscard]] std::uint8_t operator()(float v) const {
    if (!std::isfinite(v) || v <= 0.0f) return 0;
    if (v >= 1.0f) return climb(255, 1.0f);
    // v * kIntervals is exact: its interval's start is at or below v.
    return climb(interval_start_[static_cast<int>(v * kIntervals)], v);
  }

 private:
  static constexpr int kIntervals = 4096;
  [[nodiscard]] std::uint8_t climb(int k, float v) const {
    while (k < 255 && v >= first_[k + 1]) ++k;
    return static_cast<std::uint8_t>(k);
  }
  float first_[256] = {};
  std::uint8_t interval_start_[kIntervals] = {};
};

const ByteQuantizer& quantizer(PngEncoding encoding) {
  static const ByteQuantizer srgb(srgb_encode);
  static const ByteQuantizer linear([](float v) { return std::clamp(v, 0.0f, 1.0f); });
  return encoding == PngEncoding::Srgb ? srgb : linear;
}

}  // namespace

ImageFormat image_format_for(const std::string& path) {
  std::string ext = lower_extension(path);
  if (ext == ".png") return ImageFormat::Png;
  if (ext == ".exr") return ImageFormat::Exr;
  throw UsageError("output '" + path + "' must end in .png or .exr");
}

void check_output_path(const std::string& path) {
  if (path == "-") return;  // standard output
  std::error_code status_ec;
  const fs::file_status status = fs::status(path, status_ec);
  if (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status)) {
    // A device or FIFO, written in place: its folder need not be writable.
    if (access(path.c_str(), W_OK) != 0) {
      throw UsageError("output " + display_name(path) + " is not writable");
    }
    return;
  }
  fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) parent = ".";
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) {
    throw UsageError("output folder '" + parent.string() + "' does not exist");
  }
  if (access(parent.c_str(), W_OK) != 0) {
    throw UsageError("output folder '" + parent.string() + "' is not writable");
  }
  if (fs::is_directory(path, ec)) throw UsageError("output '" + path + "' is a folder");
}

PngPixels png_pixels(const Image& image, PngEncoding encoding) {
  const ByteQuantizer& to_byte = quantizer(encoding);
  PngPixels out{image.width, image.height, {}};
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  out.rgb.resize(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c) out.rgb[i * 3 + c] = to_byte(image.rgba[i * 4 + c]);
  }
  return out;
}

void write_png(const PngPixels& pixels, const std::string& path) {
  // Encoded in memory, then written by write_file_atomically, which checks
  // every write (stbi_write_png ignores fwrite's and fclose's results).
  std::string png;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(append, &png, pixels.width, pixels.height, 3, pixels.rgb.data(),
                              pixels.width * 3)) {
    throw RuntimeError("cannot write " + display_name(path) + ": the PNG encoder failed");
  }
  write_file_atomically(path, png);
}

void write_png(const Image& image, const std::string& path, PngEncoding encoding) {
  write_png(png_pixels(image, encoding), path);
}

void write_exr(const Image& image, const std::string& path) {
  // tinyexr wants planar channels in A, B, G, R order.
  const std::size_t n = static_cast<std::size_t>(image.width) * image.height;
  std::vector<float> planes[4];
  for (auto& p : planes) p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 4; ++c) planes[c][i] = image.rgba[i * 4 + static_cast<std::size_t>(c)];
  }
  EXRHeader header;
  InitEXRHeader(&header);
  EXRImage exr;
  InitEXRImage(&exr);
  float* channel_ptrs[4] = {planes[3].data(), planes[2].data(), planes[1].data(), planes[0].data()};
  exr.images = reinterpret_cast<unsigned char**>(channel_ptrs);
  exr.num_channels = 4;
  exr.width = image.width;
  exr.height = image.height;
  EXRChannelInfo channels[4] = {};
  const char* names[4] = {"A", "B", "G", "R"};
  int pixel_types[4], requested[4];
  for (int c = 0; c < 4; ++c) {
    std::snprintf(channels[c].name, sizeof channels[c].name, "%s", names[c]);
    pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    requested[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  header.num_channels = 4;
  header.channels = channels;
  header.pixel_types = pixel_types;
  header.requested_pixel_types = requested;
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;

  unsigned char* memory = nullptr;
  const char* err = nullptr;
  const std::size_t size = SaveEXRImageToMemory(&exr, &header, &memory, &err);
  if (size == 0 || memory == nullptr) {
    std::string why = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    std::free(memory);
    throw RuntimeError("cannot write " + display_name(path) + ": " + why);
  }
  const std::string exr_bytes(reinterpret_cast<const char*>(memory), size);
  std::free(memory);
  write_file_atomically(path, exr_bytes);
}

void write_image(const Image& image, const std::string& path, PngEncoding png_encoding) {
  if (image_format_for(path) == ImageFormat::Exr) {
    write_exr(image, path);
  } else {
    write_png(image, path, png_encoding);
  }
}

Image read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (data == nullptr) throw RuntimeError("cannot read PNG '" + path + "'");
  Image image(w, h);
  for (std::size_t i = 0; i < static_cast<std::size_t>(w) * h * 4; ++i) {
    image.rgba[i] = static_cast<float>(data[i]) / 255.0f;
  }
  stbi_image_free(data);
  return image;
}

}  // namespace penumbra
