#include "scene/gltf_extensions.hpp"

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

#include "io/bounded_read.hpp"
#include "penumbra/error.hpp"

namespace penumbra {

namespace {

// A .gltf's JSON with its buffers embedded as base64 can be large; the
// model reader's own limits apply to it as a whole.
constexpr std::size_t kMaxGltfBytes = std::size_t{1} << 31;

std::uint32_t little_endian_u32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

std::vector<std::string> names(const nlohmann::json& root, const char* key) {
  std::vector<std::string> out;
  const auto it = root.find(key);
  if (it == root.end() || !it->is_array()) return out;
  for (const auto& e : *it) {
    if (e.is_string()) out.push_back(e.get<std::string>());
  }
  return out;
}

}  // namespace

bool is_supported_gltf_extension(const std::string& name) {
  return name == "KHR_lights_punctual" || name == "KHR_texture_transform";
}

GltfExtensions read_gltf_extensions(const std::string& path) {
  std::string text = read_bounded_file(path, kMaxGltfBytes, "glTF file");
  // A .glb: a 12-byte header, then chunks; the first is the JSON (glTF 2.0,
  // "Binary glTF Layout").
  if (text.size() >= 20 && std::memcmp(text.data(), "glTF", 4) == 0) {
    const std::uint32_t length = little_endian_u32(text, 12);
    if (little_endian_u32(text, 16) != 0x4E4F534Au || length > text.size() - 20) {
      throw RuntimeError(path + ": the binary glTF has no JSON chunk");
    }
    text = text.substr(20, length);
  }
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    // Without nlohmann's "[json.exception.parse_error.101] " tag.
    std::string what = e.what();
    if (what.starts_with("[json.exception.") && what.find("] ") != std::string::npos) {
      what.erase(0, what.find("] ") + 2);
    }
    throw RuntimeError(path + ": not valid glTF JSON: " + what);
  }
  if (!root.is_object()) throw RuntimeError(path + ": not valid glTF JSON: not an object");
  return {names(root, "extensionsUsed"), names(root, "extensionsRequired")};
}

}  // namespace penumbra
