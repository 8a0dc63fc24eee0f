#include "gltf_files.hpp"

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "model_files.hpp"

namespace penumbra::testing {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string base64(const std::string& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned n = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    for (int k = 3; k >= 0; --k) out += table[(n >> (6 * k)) & 63];
  }
  if (i < bytes.size()) {
    unsigned n = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

template <class T>
void append(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}

json quaternion(const glm::quat& q) {
  return {q.x, q.y, q.z, q.w};
}

// The rotation that turns -z to `direction` (the way glTF cameras and
// lights look), with +y as near `up` as it can be.
glm::quat looking(const glm::vec3& direction) {
  const glm::vec3 d = glm::normalize(direction);
  const glm::vec3 up = std::abs(d.y) > 0.99f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0, 1, 0);
  return glm::quatLookAtRH(d, up);
}

std::uint32_t crc32(const std::string& data) {
  std::uint32_t c = 0xffffffffu;
  for (unsigned char byte : data) {
    c ^= byte;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return c ^ 0xffffffffu;
}

void put_be(std::string& out, std::uint32_t v) {
  for (int k = 3; k >= 0; --k) out += static_cast<char>((v >> (8 * k)) & 0xff);
}

}  // namespace

std::string write_rgba_png(const std::string& name, int width, int height,
                           const std::vector<std::uint8_t>& rgba) {
  // Filter 0 rows, deflated as stored blocks (no compression needed here).
  std::string raw;
  for (int y = 0; y < height; ++y) {
    raw += '\0';
    raw.append(reinterpret_cast<const char*>(rgba.data()) + std::size_t{4} * width * y,
               std::size_t{4} * width);
  }
  std::string z = "\x78\x01";
  for (std::size_t at = 0; at < raw.size() || at == 0;) {
    const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
    const bool last = at + n == raw.size();
    z += static_cast<char>(last ? 1 : 0);
    z += static_cast<char>(n & 0xff);
    z += static_cast<char>(n >> 8);
    z += static_cast<char>(~n & 0xff);
    z += static_cast<char>((~n >> 8) & 0xff);
    z.append(raw, at, n);
    at += n;
    if (last) break;
  }
  std::uint32_t a = 1, b = 0;
  for (unsigned char c : raw) {
    a = (a + c) % 65521;
    b = (b + a) % 65521;
  }
  put_be(z, (b << 16) | a);
  const auto chunk = [](std::string& out, const char* type, const std::string& data) {
    put_be(out, static_cast<std::uint32_t>(data.size()));
    const std::string typed = std::string(type) + data;
    out += typed;
    put_be(out, crc32(typed));
  };
  std::string header;
  put_be(header, static_cast<std::uint32_t>(width));
  put_be(header, static_cast<std::uint32_t>(height));
  header += std::string("\x08\x06\x00\x00\x00", 5);
  std::string png = "\x89PNG\r\n\x1a\n";
  chunk(png, "IHDR", header);
  chunk(png, "IDAT", z);
  chunk(png, "IEND", "");
  return write_model_file(name, png);
}

std::string write_gltf(const std::string& name, const GltfSpec& spec) {
  std::string buffer;
  json nodes = json::array(), scene_nodes = json::array(), meshes = json::array();
  json accessors = json::array(), views = json::array();
  for (std::size_t q = 0; q < spec.quads.size(); ++q) {
    const GltfQuad& quad = spec.quads[q];
    const std::size_t at = buffer.size();
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const glm::vec3& p : quad.corners) {
      append(buffer, p);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const std::array<float, 8> uv{0, 0, 1, 0, 1, 1, 0, 1};
    for (float f : uv) append(buffer, f);
    const std::array<std::uint32_t, 6> index{0, 1, 2, 0, 2, 3};
    for (std::uint32_t i : index) append(buffer, i);
    const auto view = [&](std::size_t offset, std::size_t length) {
      views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}});
      return views.size() - 1;
    };
    const std::size_t base = accessors.size();
    accessors.push_back({{"bufferView", view(at, 48)},
                         {"componentType", 5126},
                         {"count", 4},
                         {"type", "VEC3"},
                         {"min", {lo.x, lo.y, lo.z}},
                         {"max", {hi.x, hi.y, hi.z}}});
    accessors.push_back({{"bufferView", view(at + 48, 32)},
                         {"componentType", 5126},
                         {"count", 4},
                         {"type", "VEC2"}});
    accessors.push_back({{"bufferView", view(at + 80, 24)},
                         {"componentType", 5125},
                         {"count", 6},
                         {"type", "SCALAR"}});
    meshes.push_back({{"primitives",
                       {{{"attributes", {{"POSITION", base}, {"TEXCOORD_0", base + 1}}},
                         {"indices", base + 2},
                         {"material", quad.material}}}}});
    nodes.push_back({{"name", "quad" + std::to_string(q)}, {"mesh", q}});
    scene_nodes.push_back(nodes.size() - 1);
  }
  json materials = json::array(), textures = json::array(), images = json::array();
  bool transform = false;
  for (const GltfMaterialSpec& m : spec.materials) {
    json pbr = {
        {"baseColorFactor", {m.base_color.r, m.base_color.g, m.base_color.b, m.base_color.a}},
        {"metallicFactor", 0.0}};
    if (!m.image.empty()) {
      if (spec.binary) {
        std::ifstream in(fs::path(PENUMBRA_TEST_OUTPUT) / "models" / m.image, std::ios::binary);
        const std::string png((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
        while (buffer.size() % 4 != 0) buffer += '\0';
        views.push_back({{"buffer", 0}, {"byteOffset", buffer.size()}, {"byteLength", png.size()}});
        buffer += png;
        images.push_back({{"bufferView", views.size() - 1}, {"mimeType", "image/png"}});
      } else {
        images.push_back({{"uri", m.image}});
      }
      textures.push_back({{"source", images.size() - 1}, {"sampler", 0}});
      json info = {{"index", textures.size() - 1}};
      if (!m.texture_transform.empty()) {
        info["extensions"]["KHR_texture_transform"] = json::parse(m.texture_transform);
        transform = true;
      }
      pbr["baseColorTexture"] = info;
    }
    materials.push_back({{"pbrMetallicRoughness", pbr},
                         {"alphaMode", m.alpha_mode},
                         {"alphaCutoff", m.alpha_cutoff},
                         {"doubleSided", m.double_sided}});
  }
  json cameras = json::array();
  for (std::size_t c = 0; c < spec.cameras.size(); ++c) {
    const GltfCameraSpec& cam = spec.cameras[c];
    json perspective = {{"yfov", cam.yfov}, {"znear", cam.znear}, {"zfar", cam.zfar}};
    if (cam.aspect_ratio != 0.0f) perspective["aspectRatio"] = cam.aspect_ratio;
    cameras.push_back({{"type", "perspective"}, {"perspective", perspective}});
    nodes.push_back({{"name", "camera" + std::to_string(c)},
                     {"camera", c},
                     {"translation", {cam.position.x, cam.position.y, cam.position.z}},
                     {"rotation", quaternion(looking(cam.target - cam.position))}});
    scene_nodes.push_back(nodes.size() - 1);
  }
  json lights = json::array();
  for (std::size_t l = 0; l < spec.lights.size(); ++l) {
    const GltfLightSpec& light = spec.lights[l];
    json j = {{"type", light.type},
              {"color", {light.color.r, light.color.g, light.color.b}},
              {"intensity", light.intensity}};
    if (light.type == "spot") {
      j["spot"] = {{"innerConeAngle", light.inner_cone}, {"outerConeAngle", light.outer_cone}};
    }
    lights.push_back(j);
    nodes.push_back({{"name", light.name.empty() ? "light" + std::to_string(l) : light.name},
                     {"translation", {light.position.x, light.position.y, light.position.z}},
                     {"rotation", quaternion(looking(light.direction))},
                     {"extensions", {{"KHR_lights_punctual", {{"light", l}}}}}});
    scene_nodes.push_back(nodes.size() - 1);
  }
  json gltf = {{"asset", {{"version", "2.0"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", scene_nodes}}}},
               {"nodes", nodes},
               {"meshes", meshes},
               {"materials", materials},
               {"accessors", accessors},
               {"bufferViews", views},
               {"buffers",
                {{{"byteLength", buffer.size()},
                  {"uri", "data:application/octet-stream;base64," + base64(buffer)}}}}};
  json used = json::array();
  if (!cameras.empty()) gltf["cameras"] = cameras;
  if (!lights.empty()) {
    gltf["extensions"]["KHR_lights_punctual"]["lights"] = lights;
    used.push_back("KHR_lights_punctual");
  }
  if (!images.empty()) {
    gltf["images"] = images;
    gltf["textures"] = textures;
    gltf["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9987}}};
  }
  if (transform) used.push_back("KHR_texture_transform");
  for (const std::string& e : spec.extensions_used) used.push_back(e);
  for (const std::string& e : spec.extensions_required) used.push_back(e);
  if (!used.empty()) gltf["extensionsUsed"] = used;
  if (!spec.extensions_required.empty()) gltf["extensionsRequired"] = spec.extensions_required;
  if (!spec.binary) return write_model_file(name, gltf.dump());
  // glTF 2.0, "Binary glTF Layout": a 12-byte header, the JSON chunk
  // (padded with spaces), the BIN chunk (padded with zeros).
  gltf["buffers"] = {{{"byteLength", buffer.size()}}};
  std::string text = gltf.dump();
  while (text.size() % 4 != 0) text += ' ';
  while (buffer.size() % 4 != 0) buffer += '\0';
  std::string glb = "glTF";
  const auto u32 = [&](std::uint32_t v) { append(glb, v); };
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + buffer.size()));
  u32(static_cast<std::uint32_t>(text.size()));
  u32(0x4E4F534Au);  // "JSON"
  glb += text;
  u32(static_cast<std::uint32_t>(buffer.size()));
  u32(0x004E4942u);  // "BIN"
  glb += buffer;
  return write_model_file(name, glb);
}

}  // namespace penumbra::testing
