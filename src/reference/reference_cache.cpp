#include "reference/reference_cache.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/display_name.hpp"
#include "io/atomic_file.hpp"
#include "io/bounded_read.hpp"
#include "penumbra/error.hpp"

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

// The file's layout: 2 added the payload's checksum. An entry of another
// layout is a plain miss (it is re-traced and replaced, without a warning).
constexpr std::uint32_t kLayout = 2;

struct Header {
  char magic[8];
  std::uint32_t version;
  std::uint32_t layout;
  std::uint64_t key;
  std::int32_t width;
  std::int32_t height;
  std::uint64_t checksum;  // FNV-1a of everything after the header
};

std::size_t payload_size(int width, int height) {
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  return n * sizeof(float) + n;
}

}  // namespace

std::uint64_t reference_key(const TriangleMesh& mesh, const SurfacePoints& surfaces,
                            const ReferenceLight& light, int samples, std::uint64_t cutouts) {
  Fnv1a h;
  h.value(kReferenceFormatVersion);
  if (cutouts != 0) h.value(cutouts);  // keys of scenes without cut-outs are unchanged
  h.value(mesh.vertices.size());
  for (const Vertex& v : mesh.vertices) {
    h.value(v.position);
    h.value(v.normal);  // the ray origins' smooth surface (terminator_offset.hpp)
  }
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

std::uint64_t cache_checksum(std::string_view payload) {
  Fnv1a h;
  h.bytes(payload.data(), payload.size());
  return h.digest();
}

std::optional<Image> parse_cached_reference(std::string_view bytes, std::uint64_t key, int width,
                                            int height, std::string& problem) {
  problem.clear();
  Header header{};
  if (bytes.size() < sizeof header) {
    problem = "it is shorter than its header";
    return std::nullopt;
  }
  std::memcpy(&header, bytes.data(), sizeof header);
  if (std::memcmp(header.magic, kMagic, sizeof kMagic) != 0) {
    problem = "it is not a reference cache entry";
    return std::nullopt;
  }
  if (header.version != kReferenceFormatVersion || header.layout != kLayout) return std::nullopt;
  if (header.key != key || header.width != width || header.height != height || width <= 0 ||
      height <= 0) {
    problem = "its header does not match its name";
    return std::nullopt;
  }
  const std::string_view payload = bytes.substr(sizeof header);
  if (payload.size() != payload_size(width, height)) {
    problem = "its size is wrong (" + std::to_string(bytes.size()) + " bytes)";
    return std::nullopt;
  }
  if (cache_checksum(payload) != header.checksum) {
    problem = "its checksum does not match its data";
    return std::nullopt;
  }
  const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  Image image(width, height);
  for (std::size_t i = 0; i < n; ++i) {
    float visibility = 0.0f;
    std::memcpy(&visibility, payload.data() + i * sizeof(float), sizeof visibility);
    const auto alpha = static_cast<unsigned char>(payload[n * sizeof(float) + i]);
    // A visibility is a fraction of rays; anything else is damage the
    // checksum happened to miss.
    if (!(visibility >= 0.0f && visibility <= 1.0f) || alpha > 1) {
      problem = "it holds a value that is not a visibility";
      return std::nullopt;
    }
    image.rgba[4 * i] = image.rgba[4 * i + 1] = image.rgba[4 * i + 2] = visibility;
    image.rgba[4 * i + 3] = alpha ? 1.0f : 0.0f;
  }
  return image;
}

std::optional<Image> load_cached_reference(const std::string& dir, std::uint64_t key, int width,
                                           int height) {
  const std::string path = cached_reference_path(dir, key);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;  // not cached
  auto warn = [&](const std::string& why) {
    std::fprintf(stderr,
                 "penumbra: warning: ignoring the cached reference %s: %s; tracing it anew\n",
                 display_name(path).c_str(), why.c_str());
  };
  // Something else in its place (a folder, a FIFO): storing the new
  // reference says why it cannot be replaced, or replaces it.
  if (!S_ISREG(st.st_mode)) return std::nullopt;
  std::string bytes;
  try {
    bytes = read_bounded_file(path, sizeof(Header) + payload_size(width, height), "cache entry");
  } catch (const RuntimeError& e) {
    warn(e.what());
    return std::nullopt;
  }
  std::string problem;
  std::optional<Image> image = parse_cached_reference(bytes, key, width, height, problem);
  if (!image && !problem.empty()) warn(problem);
  return image;
}

void store_cached_reference(const std::string& dir, std::uint64_t key, const Image& reference) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw RuntimeError("cannot create cache folder '" + dir + "': " + ec.message());
  Header header{};
  std::memcpy(header.magic, kMagic, sizeof kMagic);
  header.version = kReferenceFormatVersion;
  header.layout = kLayout;
  header.key = key;
  header.width = reference.width;
  header.height = reference.height;
  const std::size_t n = static_cast<std::size_t>(reference.width) * reference.height;
  std::string bytes(sizeof header + payload_size(reference.width, reference.height), '\0');
  char* visibility = bytes.data() + sizeof header;
  char* alpha = visibility + n * sizeof(float);
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(visibility + i * sizeof(float), &reference.rgba[4 * i], sizeof(float));
    alpha[i] = reference.rgba[4 * i + 3] >= 0.5f ? 1 : 0;
  }
  header.checksum = cache_checksum(std::string_view(bytes).substr(sizeof header));
  std::memcpy(bytes.data(), &header, sizeof header);
  // The cache is ours: whatever is in the entry's place (a FIFO, a device)
  // is replaced, never written into.
  write_file_atomically(cached_reference_path(dir, key), bytes, ExistingOutput::Replace);
}

}  // namespace penumbra
