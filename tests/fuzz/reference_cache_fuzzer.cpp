// Traced-reference cache entries: any bytes are read as an image or
// refused, never a crash; an image read back holds visibilities in [0, 1].
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "reference/reference_cache.hpp"

namespace {

// Header offsets (reference_cache.cpp): key at 16, width at 24, height at
// 28, the checksum at 32, the payload from 40.
constexpr std::size_t kHeader = 40;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  // The key and size the entry claims, so that inputs get past the header
  // (small sizes only, to keep runs fast).
  std::uint64_t key = 0;
  std::int32_t width = 2, height = 2;
  if (size >= kHeader) {
    std::memcpy(&key, data + 16, sizeof key);
    std::memcpy(&width, data + 24, sizeof width);
    std::memcpy(&height, data + 28, sizeof height);
    if (width < -4 || width > 64 || height < -4 || height > 64) width = height = 2;
    // Inputs ending in an odd byte get the checksum right, so that the
    // checks after it are reached too.
    if (data[size - 1] & 1) {
      const std::uint64_t sum = penumbra::cache_checksum(std::string_view(bytes).substr(kHeader));
      std::memcpy(bytes.data() + 32, &sum, sizeof sum);
    }
  }
  std::string problem;
  const std::optional<penumbra::Image> image =
      penumbra::parse_cached_reference(bytes, key, width, height, problem);
  if (image) {
    if (image->width != width || image->height != height) std::abort();
    for (std::size_t i = 0; i < image->rgba.size(); ++i) {
      if (!(image->rgba[i] >= 0.0f && image->rgba[i] <= 1.0f)) std::abort();
    }
  }
  // Through the file reader as well, one input in eight (file I/O is slow).
  if (size > 0 && data[0] % 8 == 0) {
    static const std::string dir = [] {
      const std::string d = "/tmp/penumbra-fuzz-cache-" + std::to_string(getpid());
      std::filesystem::create_directories(d);
      return d;
    }();
    const std::string path = penumbra::cached_reference_path(dir, key);
    {
      std::ofstream out(path, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    }
    penumbra::load_cached_reference(dir, key, width, height);
    std::filesystem::remove(path);
  }
  return 0;
}
