#include "reference/reference_cache.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace penumbra {

namespace fs = std::filesystem;

namespace {

// 64-bit FNV-1a (Fowler, Noll, Vo): simple, stable across platforms and
// runs, and good enough to tell inputs apart for a cache.
class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      hash_ ^= p[i];
      hash_ *= 0x100000001b3ull;
    }
  }
  template <class T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  [[nodiscard]] std::uint64_t digest() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

constexpr char kMagic[8] = {'P', 'N', 'M', 'B', 'R', 'E', 'F', '\n'};

struct Header {
  char magic[8];
  std::uint32_t version;
  std::uint32_t reserved;
  std::uint64_t key;
  std::int32_t width;
  std::int32_t height;
};

}  // namespace

std::uint64_t reference_key(const TriangleMesh& mesh, const SurfacePoints& surfaces,
                            const ReferenceLight& light, int samples) {
  Fnv1a h;
  h.value(kReferenceFormatVersion);
  h.value(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) h.value(v.position);
  h.value(mesh.indices.size());
  h.bytes(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
  h.value(light.type);
  h.value(light.position);
  h.value(light.direction);
  h.value(light.axis_u);
  h.value(light.axis_v);
  h.value(light.size);
  h.value(light.cos_cone);
  h.value(light.size > 0.0f ? samples : 1);  // a point light takes one ray whatever is asked
  h.value(surfaces.width);
  h.value(surfaces.height);
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    h.value(surfaces.covered[i]);
    if (!surfaces.covered[i]) continue;
    h.value(surfaces.position[i]);
    h.value(surfaces.normal[i]);
    h.value(surfaces.position_error[i]);
  }
  return h.digest();
}

std::string default_cache_dir() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return (fs::path(xdg) / "penumbra").string();
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return (fs::path(home) / ".cache" / "penumbra").string();
  }
  return {};
}

std::string cached_reference_path(const std::string& dir, std::uint64_t key) {
  char name[40];
  std::snprintf(name, sizeof name, "reference-%016llx.bin", static_cast<unsigned long long>(key));
  return (fs::path(dir) / name).string();
}

std::optional<Image> load_cached_reference(const std::string& dir, std::uint64_t key, int width,
                                           int height) {
  std::ifstream in(cached_reference_path(dir, key), std::ios::binary);
  if (!in) return std::nullopt;
  Header header{};
  in.read(reinterpret_cast<char*>(&header), sizeof header);
  if (!in || std::memcmp(header.magic, kMagic, sizeof kMagic) != 0 ||
      header.version != kReferenceFormatVersion || header.key != key || header.width != width ||
      header.height != height) {
    return std::nullopt;
  }
  const std::size_t n = static_cast<std::size_t>(width) * height;
  std::vector<float> visibility(n);
  std::vector<std::uint8_t> alpha(n);
  in.read(reinterpret_cast<char*>(visibility.data()),
          static_cast<std::streamsize>(n * sizeof(float)));
  in.read(reinterpret_cast<char*>(alpha.data()), static_cast<std::streamsize>(n));
  if (!in || in.peek() != std::char_traits<char>::eof()) return std::nullopt;
  Image image(width, height);
  for (std::size_t i = 0; i < n; ++i) {
    image.rgba[4 * i] = image.rgba[4 * i + 1] = image.rgba[4 * i + 2] = visibility[i];
    image.rgba[4 * i + 3] = alpha[i] ? 1.0f : 0.0f;
  }
  return image;
}

void store_cached_reference(const std::string& dir, std::uint64_t key, const Image& reference) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw RuntimeError("cannot create cache folder '" + dir + "': " + ec.message());
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.version = kReferenceFormatVersion;
  header.key = key;
  header.width = reference.width;
  header.height = reference.height;
  const std::size_t n = static_cast<std::size_t>(reference.width) * reference.height;
  std::string bytes(sizeof header + n * sizeof(float) + n, '\0');
  std::memcpy(bytes.data(), &header, sizeof header);
  char* visibility = bytes.data() + sizeof header;
  char* alpha = visibility + n * sizeof(float);
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(visibility + i * sizeof(float), &reference.rgba[4 * i], sizeof(float));
    alpha[i] = reference.rgba[4 * i + 3] >= 0.5f ? 1 : 0;
  }
  write_file_atomically(cached_reference_path(dir, key), bytes);
}

}  // namespace penumbra
