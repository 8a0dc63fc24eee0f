#include "scene/model.hpp"

#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/DefaultLogger.hpp>
#include <assimp/LogStream.hpp>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <type_traits>

#include "core/child_process.hpp"
#include "penumbra/error.hpp"
#include "scene/direct_readers.hpp"
#include "scene/gltf_extensions.hpp"
#include "scene/gltf_lights.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/smooth_normals.hpp"
#include "scene/texture.hpp"

namespace penumbra {

namespace {

namespace fs = std::filesystem;

// Normals the file lacks are smoothed only across edges where the faces
// meet at less than this: a scanned model (the bunny) comes out smooth, a
// box keeps its edges.
constexpr float kCreaseDegrees = 80.0f;

// - Triangulate: the renderer draws triangles; polygons are split, points
//   and lines stay as they are and are skipped below.
// - JoinIdenticalVertices: OBJ, PLY and STL readers emit one vertex per face
//   corner; joining them shares vertices (a third of the memory, and a
//   smaller problem for with_smooth_normals).
// - PreTransformVertices: applies the node hierarchy (glTF and others place
//   meshes with node transforms), so the model is one object-space soup.
// - RemoveRedundantMaterials: merges identical materials, so fewer are
//   appended to the scene.
// - ValidateDataStructure: assimp's own consistency check; the indices and
//   positions are checked here too, before and after these steps.
// Not GenSmoothNormals: with a crease angle it took 4.3 of the 5.7 s a
// million-triangle OBJ needed; with_smooth_normals does the same in a
// fraction of that. Not FindInvalidData: it deletes a whole mesh with one
// non-finite position without failing, which would draw a silently
// incomplete model; such a file is an error here.
constexpr unsigned kPostProcess =
    aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
    aiProcess_RemoveRedundantMaterials | aiProcess_ValidateDataStructure;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw RuntimeError(path + ": " + what);
}

// Assimp's messages can span lines; the CLI prints one.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && (text.back() == ' ' || text.back() == '\r')) text.pop_back();
  return text;
}

// Assimp catches std::bad_alloc and reports it as its error text; it is
// rethrown, so the reader reports the memory limit.
[[noreturn]] void fail_import(const std::string& path, const Assimp::Importer& importer) {
  const std::string error = one_line(importer.GetErrorString());
  if (error.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
  // Assimp says "no suitable reader found" for a glTF whose JSON (or GLB
  // header) it cannot parse: say what is wrong with it instead.
  if (error.find("No suitable reader") != std::string::npos && is_gltf_path(path)) {
    read_gltf_extensions(path);  // throws "<path>: not valid glTF JSON: ..."
  }
  fail(path, "cannot read the model: " + error);
}

// Errors assimp would report vaguely ("no suitable reader") or not at all.
void check_readable(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a folder, not a model file");
  // A pipe or a device could block or never end.
  if (!fs::is_regular_file(status)) fail(path, "is not a regular file");
  if (!std::ifstream(path, std::ios::binary)) fail(path, "cannot be opened for reading");
  if (fs::file_size(path, ec) == 0 && !ec) fail(path, "the file is empty");
}

// A file that starts "ply" (in any case, as assimp's PLY reader takes it,
// whatever the file's name) must have "end_header" in its first megabyte:
// without it, the reader never returns.
void check_ply_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(1 << 20, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (head.rfind("ply", 0) == 0 && head.find("end_header") == std::string::npos) {
    fail(path, "the PLY header has no end_header line");
  }
}

// Assimp's warnings while one file is read. Some readers repair bad data
// with only a warning (glTF drops the faces whose indices are out of
// range); such a file is an error here. Assimp has one logger per process:
// this creates it for the duration of one load (or listens to the one the
// program made), so loads must not run concurrently (scenes are loaded on
// one thread).
class ImportWarnings {
 public:
  ImportWarnings() : own_logger_(Assimp::DefaultLogger::isNullLogger()) {
    if (own_logger_) Assimp::DefaultLogger::create(nullptr, Assimp::Logger::NORMAL, 0);
    Assimp::DefaultLogger::get()->attachStream(stream_, kSeverities);
  }
  ~ImportWarnings() {
    if (own_logger_) {
      Assimp::DefaultLogger::kill();  // deletes the stream
    } else {
      Assimp::DefaultLogger::get()->detachStream(stream_, kSeverities);
      delete stream_;
    }
  }
  ImportWarnings(const ImportWarnings&) = delete;
  ImportWarnings& operator=(const ImportWarnings&) = delete;

  // Fails on a warning that says data was out of range (and so dropped).
  void check(const std::string& path) const {
    for (const std::string& message : messages_) {
      std::string lower = message;
      for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (lower.find("out-of-range") != std::string::npos ||
          lower.find("out of range") != std::string::npos) {
        fail(path, one_line(message));
      }
    }
  }

 private:
  class Stream : public Assimp::LogStream {
   public:
    explicit Stream(std::vector<std::string>& messages) : messages_(messages) {}
    // Drops the logger's "Warn,  T0: " prefix.
    void write(const char* message) override {
      std::string text = message;
      const std::size_t colon = text.find(": ");
      if (colon != std::string::npos && text.find(',') < colon) text.erase(0, colon + 2);
      messages_.push_back(std::move(text));
    }

   private:
    std::vector<std::string>& messages_;
  };
  static constexpr unsigned kSeverities = Assimp::Logger::Warn | Assimp::Logger::Err;
  std::vector<std::string> messages_;
  bool own_logger_;
  Stream* stream_ = new Stream(messages_);  // owned by the logger while attached
};

bool finite(const aiVector3D& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string describe(const aiVector3D& v) {
  std::ostringstream out;
  out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
  return out.str();
}

bool read_color(const aiMaterial& m, const char* key, unsigned type, unsigned index,
                glm::vec3& out) {
  aiColor4D c;
  if (m.Get(key, type, index, c) != AI_SUCCESS) return false;
  if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) return false;
  out = glm::clamp(glm::vec3(c.r, c.g, c.b), glm::vec3(0.0f), glm::vec3(1.0f));
  return true;
}

// Textures of one model, each decoded once however many materials use it.
class TextureReader {
 public:
  TextureReader(const aiScene& scene, const std::string& model_path,
                std::vector<std::string>& warnings)
      : scene_(scene),
        model_path_(model_path),
        folder_(fs::path(model_path).parent_path()),
        warnings_(warnings) {}

  // The texture a material names, or null (with a warning) if it cannot be
  // read.
  std::shared_ptr<const TextureImage> get(const std::string& reference) {
    auto [it, added] = cache_.try_emplace(reference);
    if (added) it->second = read(reference);
    return it->second;
  }

 private:
  std::shared_ptr<const TextureImage> read(const std::string& reference) {
    std::string error;
    std::optional<TextureImage> image;
    std::string name = reference;
    if (const aiTexture* embedded = scene_.GetEmbeddedTexture(reference.c_str())) {
      name = model_path_ + ": embedded texture " + reference;
      if (embedded->mHeight == 0) {  // compressed: mWidth bytes of a PNG, JPEG, ...
        image = decode_texture(reinterpret_cast<const std::uint8_t*>(embedded->pcData),
                               embedded->mWidth, name, error);
      } else {  // raw aiTexel, BGRA
        TextureImage raw;
        raw.name = name;
        raw.width = static_cast<int>(embedded->mWidth);
        raw.height = static_cast<int>(embedded->mHeight);
        const std::size_t count = std::size_t{embedded->mWidth} * embedded->mHeight;
        raw.rgba.resize(4 * count);
        for (std::size_t i = 0; i < count; ++i) {
          const aiTexel& t = embedded->pcData[i];
          raw.rgba[4 * i] = t.r;
          raw.rgba[4 * i + 1] = t.g;
          raw.rgba[4 * i + 2] = t.b;
          raw.rgba[4 * i + 3] = t.a;
        }
        image = std::move(raw);
      }
    } else if (reference.empty() || reference.starts_with("data:")) {
      // Assimp embeds base64 data URIs (above); it hands any other data:
      // URI on as it is (or as an empty name), which is not a file beside
      // the scene, so it is not looked for there.
      name = model_path_ + ": a texture";
      error =
          "its image is a data: URI that is not base64 (or has no name), which penumbra "
          "does not read";
    } else {
      // OBJ files written on Windows separate folders with backslashes.
      std::string relative = reference;
      std::replace(relative.begin(), relative.end(), '\\', '/');
      const fs::path file = folder_ / relative;
      name = file.string();
      std::error_code ec;
      if (!fs::is_regular_file(file, ec)) {
        error = fs::exists(file, ec) ? "is not a regular file" : "no such file";
      } else if (fs::file_size(file, ec) > kMaxTextureFileBytes) {
        // Refused unread: an image file that large would take the model
        // reader's memory before it could be decoded (and refused).
        error = "the file is larger than the " + std::to_string(kMaxTextureFileBytes >> 20) +
                " MiB penumbra reads for a texture";
      } else {
        image = read_texture(file.string(), error);
      }
    }
    if (!image) {
      warnings_.push_back(name + ": " + error + "; using the material's flat colour");
      return nullptr;
    }
    return std::make_shared<const TextureImage>(std::move(*image));
  }

  const aiScene& scene_;
  std::string model_path_;
  fs::path folder_;
  std::vector<std::string>& warnings_;
  std::map<std::string, std::shared_ptr<const TextureImage>> cache_;
};

TextureWrap to_wrap(int mode) {
  switch (mode) {
    case aiTextureMapMode_Clamp:
    case aiTextureMapMode_Decal:
      return TextureWrap::ClampToEdge;
    case aiTextureMapMode_Mirror:
      return TextureWrap::MirroredRepeat;
    default:
      return TextureWrap::Repeat;
  }
}

// glTF's KHR_texture_transform as assimp 5.2 stores it: it negates the
// rotation and moves the translation so that the transform turns about
// the texture's centre in its v-flipped coordinates (glTF2Importer.cpp).
// This undoes that, then maps uv (v up) to the image's coordinates:
// glTF's uv' = T(offset) R(rotation) S(scale) uv, on uv with v down.
glm::mat3x2 gltf_uv_transform(const aiUVTransform& t) {
  const float sx = t.mScaling.x, sy = t.mScaling.y;
  const float rotation = -t.mRotation;
  const float c = std::cos(rotation), s = std::sin(rotation);
  const float offset_x = t.mTranslation.x - 0.5f * sx * (-c + s + 1.0f);
  const float offset_y = -(t.mTranslation.y - 0.5f * sy * (s + c - 1.0f) - 1.0f + sy);
  // glTF's matrix (column-major): [[c, -s], [s, c]] * diag(sx, sy), then
  // the offset; applied to (u, 1 - v).
  const glm::mat3 gltf(glm::vec3(c * sx, -s * sx, 0.0f), glm::vec3(s * sy, c * sy, 0.0f),
                       glm::vec3(offset_x, offset_y, 1.0f));
  const glm::mat3 flip(glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f),
                       glm::vec3(0.0f, 1.0f, 1.0f));
  return glm::mat3x2(gltf * flip);
}

// OBJ's map_d as the base colour's alpha: the opacity image's alpha (or
// its grey level, for an image without alpha) at the same texture
// coordinate, nearest texel.
std::shared_ptr<const TextureImage> with_opacity(const std::shared_ptr<const TextureImage>& base,
                                                 const TextureImage& opacity) {
  TextureImage out;
  if (base != nullptr) {
    out = *base;
  } else {
    out.name = opacity.name;
    out.width = opacity.width;
    out.height = opacity.height;
    out.rgba.assign(opacity.rgba.size(), 255);
  }
  bool has_alpha = false;
  for (std::size_t i = 3; i < opacity.rgba.size(); i += 4) has_alpha |= opacity.rgba[i] != 255;
  for (int y = 0; y < out.height; ++y) {
    const int oy = y * opacity.height / out.height;
    for (int x = 0; x < out.width; ++x) {
      const int ox = x * opacity.width / out.width;
      const std::size_t o = 4 * (static_cast<std::size_t>(oy) * opacity.width + ox);
      out.rgba[4 * (static_cast<std::size_t>(y) * out.width + x) + 3] =
          opacity.rgba[o + (has_alpha ? 3 : 0)];
    }
  }
  return std::make_shared<const TextureImage>(std::move(out));
}

// The base colour (glTF's metallic-roughness model) or else the diffuse
// colour (OBJ's Kd, PLY, ...), both linear, and its texture; the specular
// colour and exponent where the file has them; glTF's alpha mode, cutoff
// and doubleSided; OBJ's map_d as a mask.
Material to_material(const aiMaterial& m, TextureReader& textures) {
  Material out;
  aiString name;
  if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
  if (!read_color(m, AI_MATKEY_BASE_COLOR, out.albedo)) {
    read_color(m, AI_MATKEY_COLOR_DIFFUSE, out.albedo);
  }
  read_color(m, AI_MATKEY_COLOR_SPECULAR, out.specular);
  float shininess = 0.0f;
  // Assimp reports 0 for "not given" in some readers: keep the default then.
  if (m.Get(AI_MATKEY_SHININESS, shininess) == AI_SUCCESS && std::isfinite(shininess) &&
      shininess >= 1.0f) {
    out.shininess = std::min(shininess, 10000.0f);
  }
  float opacity = 1.0f;
  if (m.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && std::isfinite(opacity)) {
    out.alpha = std::clamp(opacity, 0.0f, 1.0f);
  }
  aiString alpha_mode;
  const bool gltf = m.Get(AI_MATKEY_GLTF_ALPHAMODE, alpha_mode) == AI_SUCCESS;
  if (gltf) {
    const std::string mode = alpha_mode.C_Str();
    out.alpha_mode = mode == "MASK"    ? AlphaMode::Mask
                     : mode == "BLEND" ? AlphaMode::Blend
                                       : AlphaMode::Opaque;
    float cutoff = 0.5f;
    if (m.Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff) == AI_SUCCESS && std::isfinite(cutoff)) {
      out.alpha_cutoff = std::clamp(cutoff, 0.0f, 1.0f);
    }
    int two_sided = 0;
    out.double_sided = m.Get(AI_MATKEY_TWOSIDED, two_sided) == AI_SUCCESS && two_sided != 0;
  }

  aiString file;
  const aiTextureType type = m.GetTextureCount(aiTextureType_BASE_COLOR) > 0
                                 ? aiTextureType_BASE_COLOR
                                 : aiTextureType_DIFFUSE;
  if (m.GetTextureCount(type) > 0 &&
      m.GetTexture(type, 0, &file, nullptr, nullptr, nullptr, nullptr) == AI_SUCCESS) {
    out.texture = textures.get(file.C_Str());
    int mode = 0;
    if (m.Get(AI_MATKEY_MAPPINGMODE_U(type, 0), mode) == AI_SUCCESS) out.wrap_s = to_wrap(mode);
    if (m.Get(AI_MATKEY_MAPPINGMODE_V(type, 0), mode) == AI_SUCCESS) out.wrap_t = to_wrap(mode);
    int filter = 0;
    // glTF's magFilter: 9728 is NEAREST.
    if (m.Get(AI_MATKEY_GLTF_MAPPINGFILTER_MAG(type, 0), filter) == AI_SUCCESS) {
      out.nearest_magnification = filter == 9728;
    }
    aiUVTransform transform;
    if (gltf && m.Get(AI_MATKEY_UVTRANSFORM(type, 0), transform) == AI_SUCCESS) {
      out.uv_transform = gltf_uv_transform(transform);
    }
  }
  // OBJ's map_d: a cut-out mask (OBJ has no alpha mode; a mask is what
  // such a texture is for on leaves and fences).
  if (!gltf && m.GetTextureCount(aiTextureType_OPACITY) > 0 &&
      m.GetTexture(aiTextureType_OPACITY, 0, &file) == AI_SUCCESS) {
    if (auto opacity = textures.get(file.C_Str())) {
      out.texture = with_opacity(out.texture, *opacity);
      out.alpha_mode = AlphaMode::Mask;
    }
  }
  return out;
}

// The file's data as its reader gave it, before any step can hide a
// problem (JoinIdenticalVertices merges a non-finite position into a
// neighbour): finite positions, indices in range, and some polygon (not
// only points and lines) to draw.
void check_raw(const std::string& path, const aiScene& scene) {
  bool has_polygon = false;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (mesh == nullptr) continue;
    const std::string where = "mesh " + std::to_string(m);
    if (mesh->mVertices == nullptr && mesh->mNumVertices > 0)
      fail(path, where + " has no positions");
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      if (!finite(mesh->mVertices[v])) {
        fail(path, where + ", vertex " + std::to_string(v) + ": position " +
                       describe(mesh->mVertices[v]) + " is not finite");
      }
    }
    if (mesh->mFaces == nullptr && mesh->mNumFaces > 0) fail(path, where + " has no faces");
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices >= 3) has_polygon = true;
      if (face.mIndices == nullptr && face.mNumIndices > 0)
        fail(path, where + " has a broken face");
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= mesh->mNumVertices) {
          fail(path, where + ", face " + std::to_string(f) + ": vertex index " +
                         std::to_string(face.mIndices[k]) + " is out of range (the mesh has " +
                         std::to_string(mesh->mNumVertices) + " vertices)");
        }
      }
    }
  }
  if (!has_polygon) fail(path, "the file holds no triangles");
}

// Vertices whose normal is unusable take the area-weighted mean of their
// faces' normals; with only degenerate faces, +y.
void repair_normals(TriangleMesh& mesh, std::uint32_t first_vertex, std::size_t first_index,
                    const std::vector<std::uint32_t>& broken) {
  if (broken.empty()) return;
  std::vector<glm::vec3> sums(mesh.vertices.size() - first_vertex, glm::vec3(0.0f));
  for (std::size_t i = first_index; i + 2 < mesh.indices.size(); i += 3) {
    const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
    const glm::vec3 n =
        glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                   mesh.vertices[c].position - mesh.vertices[a].position);  // length: 2 x area
    for (std::uint32_t v : {a, b, c}) sums[v - first_vertex] += n;
  }
  for (std::uint32_t v : broken) {
    const glm::vec3 s = sums[v - first_vertex];
    const float length = glm::length(s);
    mesh.vertices[v].normal =
        std::isfinite(length) && length > 0.0f ? s / length : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

// Gives the vertices from first_vertex on (a mesh without normals in the
// file) their normals, splitting vertices at creases.
void smooth_normals(TriangleMesh& mesh, std::uint32_t first_vertex, std::size_t first_index) {
  TriangleMesh part;
  part.vertices.assign(mesh.vertices.begin() + first_vertex, mesh.vertices.end());
  part.indices.reserve(mesh.indices.size() - first_index);
  for (std::size_t i = first_index; i < mesh.indices.size(); ++i) {
    part.indices.push_back(mesh.indices[i] - first_vertex);
  }
  part = with_smooth_normals(part, kCreaseDegrees);
  mesh.vertices.resize(first_vertex);
  mesh.indices.resize(first_index);
  mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (std::uint32_t i : part.indices) mesh.indices.push_back(first_vertex + i);
}

// The node's transform to the file's world space (its ancestors' applied).
glm::mat4 world_transform(const aiNode* node) {
  glm::mat4 m(1.0f);
  for (; node != nullptr; node = node->mParent) {
    const aiMatrix4x4& t = node->mTransformation;  // row-major
    const glm::mat4 local(t.a1, t.b1, t.c1, t.d1, t.a2, t.b2, t.c2, t.d2, t.a3, t.b3, t.c3, t.d3,
                          t.a4, t.b4, t.c4, t.d4);
    m = local * m;
  }
  return m;
}

bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Cameras and lights, placed as glTF places them: at their node's origin,
// looking (shining) down its -z axis, the camera's up its +y (glTF 2.0,
// "Cameras"; KHR_lights_punctual). Assimp 5.2 also copies a camera's node
// translation into aiCamera::mPosition, so that is not added again here.
// A camera or light whose node is missing or degenerate is left out.
void read_cameras_and_lights(const aiScene& scene, Model& model) {
  for (unsigned i = 0; i < scene.mNumCameras; ++i) {
    const aiCamera& in = *scene.mCameras[i];
    const aiNode* node = scene.mRootNode ? scene.mRootNode->FindNode(in.mName) : nullptr;
    if (node == nullptr) continue;
    const glm::mat4 w = world_transform(node);
    ModelCamera out;
    out.name = in.mName.C_Str();
    const glm::vec3 position(w[3]);
    const glm::vec3 forward = glm::vec3(w * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    const glm::vec3 up = glm::vec3(w * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    const float length = glm::length(forward);
    if (!finite(position) || !(length > 0.0f) || !std::isfinite(length) ||
        !(glm::length(glm::cross(forward, up)) > 0.0f)) {
      continue;
    }
    out.camera.position = position;
    out.camera.target = position + forward / length;
    out.camera.up = glm::normalize(up);
    out.orthographic = in.mOrthographicWidth > 0.0f;
    // Assimp 5.2 stores glTF's yfov times aspectRatio as the horizontal
    // field of view (and the aspect ratio, 0 when the file gives none).
    // glTF requires yfov > 0 and aspectRatio > 0; a field of view outside
    // the 1 to 170 degrees penumbra renders (--camera-fov's range) would
    // show a blank image, so such a camera is an error naming it.
    const std::string camera = "camera '" + out.name + "'";
    if (!out.orthographic && (!std::isfinite(in.mAspect) || in.mAspect < 0.0f)) {
      std::ostringstream what;
      what << camera << ": aspectRatio " << in.mAspect << " is not a positive number";
      fail(model.path, what.str());
    }
    const float yfov = in.mAspect > 0.0f ? in.mHorizontalFOV / in.mAspect : in.mHorizontalFOV;
    if (!out.orthographic && !(glm::degrees(yfov) >= 1.0f && glm::degrees(yfov) <= 170.0f)) {
      std::ostringstream what;
      what << camera << ": yfov " << yfov << " radians (" << glm::degrees(yfov)
           << " degrees) is outside the 1 to 170 degrees penumbra renders";
      fail(model.path, what.str());
    }
    out.camera.fov_y_degrees = std::clamp(glm::degrees(yfov), 1.0f, 170.0f);
    if (std::isfinite(in.mClipPlaneNear) && in.mClipPlaneNear > 0.0f) {
      out.camera.near_plane = in.mClipPlaneNear;
    }
    if (std::isfinite(in.mClipPlaneFar) && in.mClipPlaneFar > out.camera.near_plane) {
      out.camera.far_plane = in.mClipPlaneFar;
    }
    model.cameras.push_back(out);
  }
  for (unsigned i = 0; i < scene.mNumLights; ++i) {
    const aiLight& in = *scene.mLights[i];
    ModelLight out;
    out.name = in.mName.C_Str();
    const aiNode* node = scene.mRootNode ? scene.mRootNode->FindNode(in.mName) : nullptr;
    if (node == nullptr) continue;
    const glm::mat4 w = world_transform(node);
    // Assimp gives colour times intensity.
    const glm::vec3 power(in.mColorDiffuse.r, in.mColorDiffuse.g, in.mColorDiffuse.b);
    if (!finite(power)) continue;
    GltfLightType type = GltfLightType::Point;
    if (in.mType == aiLightSource_DIRECTIONAL)
      type = GltfLightType::Directional;
    else if (in.mType == aiLightSource_SPOT)
      type = GltfLightType::Spot;
    else if (in.mType != aiLightSource_POINT)
      continue;
    out.light = light_from_gltf(type, power, 1.0f, in.mAngleInnerCone, in.mAngleOuterCone);
    out.light.position = glm::vec3(w[3]);
    const glm::vec3 direction = glm::vec3(w * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    if (!finite(out.light.position) || !(glm::length(direction) > 0.0f)) continue;
    out.light.direction = glm::normalize(direction);
    model.lights.push_back(out);
  }
}

// Reads and checks the model in this process.
Model read_model(const std::string& path) {
  const ImportWarnings warnings;
  Assimp::Importer importer;
  // Read, check what the reader gave, then post-process (and check again
  // while copying below).
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene == nullptr) fail_import(path, importer);
  warnings.check(path);
  check_raw(path, *scene);

  Model model;
  model.path = path;
  read_cameras_and_lights(*scene, model);
  scene = importer.ApplyPostProcessing(kPostProcess);
  if (scene == nullptr) fail_import(path, importer);
  warnings.check(path);
  if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mNumMeshes == 0) {
    fail(path, "the file holds no triangles");
  }
  TextureReader textures(*scene, path, model.warnings);
  TriangleMesh& mesh = model.mesh;
  std::size_t vertex_total = 0, face_total = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    vertex_total += scene->mMeshes[m]->mNumVertices;
    face_total += scene->mMeshes[m]->mNumFaces;
  }
  if (vertex_total > std::numeric_limits<std::uint32_t>::max()) {
    fail(path, "has " + std::to_string(vertex_total) + " vertices, more than 32-bit indices reach");
  }
  mesh.vertices.reserve(vertex_total);
  mesh.indices.reserve(3 * face_total);

  // The file's material index -> ours; only materials that triangles use.
  std::vector<int> material_of(scene->mNumMaterials, -1);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& in = *scene->mMeshes[m];
    if ((in.mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0 || in.mVertices == nullptr) continue;
    const std::string where = "mesh " + std::to_string(m);
    if (in.mMaterialIndex >= scene->mNumMaterials) {
      fail(path, where + " uses material " + std::to_string(in.mMaterialIndex) + " of " +
                     std::to_string(scene->mNumMaterials));
    }
    int& material = material_of[in.mMaterialIndex];
    if (material < 0) {
      material = static_cast<int>(model.materials.size());
      model.materials.push_back(to_material(*scene->mMaterials[in.mMaterialIndex], textures));
    }

    const std::uint32_t base = static_cast<std::uint32_t>(mesh.vertices.size());
    const std::size_t first_index = mesh.indices.size();
    std::vector<std::uint32_t> broken_normals;
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
      const aiVector3D& p = in.mVertices[v];
      if (!finite(p)) {
        fail(path, where + ", vertex " + std::to_string(v) + ": position " + describe(p) +
                       " is not finite");
      }
      glm::vec3 normal(0.0f);
      if (in.mNormals != nullptr) normal = {in.mNormals[v].x, in.mNormals[v].y, in.mNormals[v].z};
      const float length = glm::length(normal);
      if (std::isfinite(length) && length > 1e-12f) {
        normal /= length;
      } else if (in.mNormals != nullptr) {
        broken_normals.push_back(base + v);
      }
      glm::vec2 uv(0.0f);
      if (in.mTextureCoords[0] != nullptr) {
        uv = {in.mTextureCoords[0][v].x, in.mTextureCoords[0][v].y};
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = glm::vec2(0.0f);
      }
      std::uint32_t color = 0xffffffffu;
      if (in.mColors[0] != nullptr) {
        const aiColor4D& c = in.mColors[0][v];
        color = pack_color({c.r, c.g, c.b, c.a});
      }
      mesh.vertices.push_back(
          {{p.x, p.y, p.z}, normal, static_cast<std::uint32_t>(material), uv, color});
      model.bounds.extend({p.x, p.y, p.z});
    }
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (face.mNumIndices != 3) continue;  // a point or a line: no surface to draw
      for (unsigned k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= in.mNumVertices) {
          fail(path, where + ", face " + std::to_string(f) + ": vertex index " +
                         std::to_string(face.mIndices[k]) + " is out of range (the mesh has " +
                         std::to_string(in.mNumVertices) + " vertices)");
        }
        mesh.indices.push_back(base + face.mIndices[k]);
      }
    }
    if (in.mNormals != nullptr) {
      repair_normals(mesh, base, first_index, broken_normals);
    } else {
      smooth_normals(mesh, base, first_index);
    }
  }
  if (mesh.indices.empty()) fail(path, "the file holds no triangles");
  return model;
}

// The model as bytes, to pass it from the process that read it.
static_assert(std::is_trivially_copyable_v<Vertex>);

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
void put_array(std::string& out, const std::vector<T>& values) {
  put(out, static_cast<std::uint64_t>(values.size()));
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

void put_string(std::string& out, const std::string& text) {
  put(out, static_cast<std::uint64_t>(text.size()));
  out += text;
}

std::string serialize(const Model& model) {
  std::string out;
  out.reserve(32 + model.mesh.vertices.size() * sizeof(Vertex) +
              model.mesh.indices.size() * sizeof(std::uint32_t));
  put_array(out, model.mesh.vertices);
  put_array(out, model.mesh.indices);
  // Each texture once, then the materials' indices into them (-1: none).
  std::vector<const TextureImage*> textures;
  for (const Material& m : model.materials) {
    if (m.texture != nullptr &&
        std::find(textures.begin(), textures.end(), m.texture.get()) == textures.end()) {
      textures.push_back(m.texture.get());
    }
  }
  put(out, static_cast<std::uint64_t>(textures.size()));
  for (const TextureImage* t : textures) {
    put_string(out, t->name);
    put(out, t->width);
    put(out, t->height);
    put_array(out, t->rgba);
  }
  put(out, static_cast<std::uint64_t>(model.materials.size()));
  for (const Material& m : model.materials) {
    put_string(out, m.name);
    put(out, m.albedo);
    put(out, m.specular);
    put(out, m.shininess);
    put(out, m.alpha);
    put(out, m.alpha_mode);
    put(out, m.alpha_cutoff);
    put(out, m.double_sided);
    const auto it = std::find(textures.begin(), textures.end(), m.texture.get());
    put(out, m.texture == nullptr ? std::int64_t{-1} : std::int64_t(it - textures.begin()));
    put(out, m.wrap_s);
    put(out, m.wrap_t);
    put(out, m.nearest_magnification);
    put(out, m.uv_transform);
  }
  put(out, model.bounds);
  put(out, static_cast<std::uint64_t>(model.cameras.size()));
  for (const ModelCamera& c : model.cameras) {
    put_string(out, c.name);
    put(out, c.camera);
    put(out, c.orthographic);
  }
  put(out, static_cast<std::uint64_t>(model.lights.size()));
  for (const ModelLight& l : model.lights) {
    put_string(out, l.name);
    put(out, l.light);
  }
  put(out, static_cast<std::uint64_t>(model.warnings.size()));
  for (const std::string& w : model.warnings) put_string(out, w);
  return out;
}

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  const char* take(std::size_t size) {
    if (size > bytes_.size() - at_) throw std::logic_error("model bytes end early");
    const char* p = bytes_.data() + at_;
    at_ += size;
    return p;
  }
  template <class T>
  T get() {
    T value;
    std::memcpy(&value, take(sizeof value), sizeof value);
    return value;
  }
  template <class T>
  void get_array(std::vector<T>& values) {
    const auto count = get<std::uint64_t>();
    if (count > (bytes_.size() - at_) / sizeof(T)) throw std::logic_error("model bytes end early");
    values.resize(count);
    std::memcpy(values.data(), take(count * sizeof(T)), count * sizeof(T));
  }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

Model deserialize(const std::string& path, const std::string& bytes) {
  Model model;
  model.path = path;
  Reader in(bytes);
  const auto text = [&] {
    const auto length = in.get<std::uint64_t>();
    return std::string(in.take(length), length);
  };
  in.get_array(model.mesh.vertices);
  in.get_array(model.mesh.indices);
  std::vector<std::shared_ptr<const TextureImage>> textures(in.get<std::uint64_t>());
  for (auto& texture : textures) {
    TextureImage t;
    t.name = text();
    t.width = in.get<int>();
    t.height = in.get<int>();
    in.get_array(t.rgba);
    texture = std::make_shared<const TextureImage>(std::move(t));
  }
  const auto materials = in.get<std::uint64_t>();
  for (std::uint64_t i = 0; i < materials; ++i) {
    Material m;
    m.name = text();
    m.albedo = in.get<glm::vec3>();
    m.specular = in.get<glm::vec3>();
    m.shininess = in.get<float>();
    m.alpha = in.get<float>();
    m.alpha_mode = in.get<AlphaMode>();
    m.alpha_cutoff = in.get<float>();
    m.double_sided = in.get<bool>();
    const auto texture = in.get<std::int64_t>();
    if (texture >= 0) m.texture = textures.at(static_cast<std::size_t>(texture));
    m.wrap_s = in.get<TextureWrap>();
    m.wrap_t = in.get<TextureWrap>();
    m.nearest_magnification = in.get<bool>();
    m.uv_transform = in.get<glm::mat3x2>();
    model.materials.push_back(std::move(m));
  }
  model.bounds = in.get<Bounds>();
  model.cameras.resize(in.get<std::uint64_t>());
  for (ModelCamera& c : model.cameras) {
    c.name = text();
    c.camera = in.get<Camera>();
    c.orthographic = in.get<bool>();
  }
  model.lights.resize(in.get<std::uint64_t>());
  for (ModelLight& l : model.lights) {
    l.name = text();
    l.light = in.get<Light>();
  }
  model.warnings.resize(in.get<std::uint64_t>());
  for (std::string& w : model.warnings) w = text();
  return model;
}

// How long the reader may take: far longer than a sound file needs (a
// million-triangle OBJ, 50 MB, reads in under 2 s), short enough that a
// reader caught in a loop is stopped.
std::chrono::milliseconds read_time_limit(std::uintmax_t file_size) {
  const auto megabytes = static_cast<double>(file_size) / (1 << 20);
  return std::chrono::milliseconds(10'000 + static_cast<long long>(2'000.0 * megabytes));
}

// How much address space the reader may take: kReaderMemoryFloor, plus
// kReaderMemoryPerFileByte per byte of the file. A sound file needs far
// less (a million-triangle OBJ, 50 MB, peaks near 1 GB); a hostile one
// (a 309-byte OFF file whose header promises billions of vertices) is
// stopped at the floor instead of taking the machine's memory.
std::size_t read_memory_limit(std::uintmax_t file_size) {
  const std::uintmax_t limit = kReaderMemoryFloor + kReaderMemoryPerFileByte * file_size;
  return static_cast<std::size_t>(std::min<std::uintmax_t>(limit, std::uintmax_t{1} << 46));
}

bool has_extension(const std::string& path, const char* extension) {
  std::string e = fs::path(path).extension().string();
  for (char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e == extension;
}

// The material assimp 5.2 gives a file without one, as to_material reads
// it: the OBJ reader's "DefaultMaterial" (diffuse 0.6, no specular), the
// PLY reader's unnamed white one (diffuse and specular 1).
Material default_file_material(bool obj) {
  Material m;
  if (obj) {
    m.name = "DefaultMaterial";
    m.albedo = glm::vec3(0.6f);
    m.specular = glm::vec3(0.0f);
  } else {
    m.albedo = glm::vec3(1.0f);
    m.specular = glm::vec3(1.0f);
  }
  return m;
}

// The model the direct readers read, finished as read_model finishes
// assimp's: unit normals (unusable ones repaired) or smooth ones computed.
Model finish_direct(const std::string& path, DirectMesh in, bool obj) {
  Model model;
  model.path = path;
  model.materials.push_back(default_file_material(obj));
  TriangleMesh& mesh = in.mesh;
  if (in.has_normals) {
    std::vector<std::uint32_t> broken;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      glm::vec3& normal = mesh.vertices[v].normal;
      const float length = glm::length(normal);
      if (std::isfinite(length) && length > 1e-12f) {
        normal /= length;
      } else {
        broken.push_back(static_cast<std::uint32_t>(v));
      }
    }
    repair_normals(mesh, 0, 0, broken);
  } else {
    mesh = with_smooth_normals(mesh, kCreaseDegrees);
  }
  for (const Vertex& v : mesh.vertices) model.bounds.extend(v.position);
  model.mesh = std::move(mesh);
  return model;
}

// The model read by a direct reader, or nullopt for a file they leave to assimp.
std::optional<Model> read_directly(const std::string& path) {
  std::optional<DirectMesh> mesh;
  const bool obj = has_extension(path, ".obj");
  if (obj) {
    mesh = read_obj_directly(path);
  } else if (has_extension(path, ".ply")) {
    mesh = read_ply_directly(path);
  }
  if (!mesh) return std::nullopt;
  return finish_direct(path, std::move(*mesh), obj);
}

}  // namespace

// Assimp's readers can crash or never return on malformed files (fuzzing
// assimp 5.2 found OFF files that crash its reader and PLY files it never
// finishes), so the model is read in a child process: such a file costs an
// error naming it, not the program.
Model load_model(const std::string& path, ModelReader reader) {
  check_readable(path);
  // The direct readers are ours, bounded by the file's size and checked
  // for every malformed input the fuzzer and the tests throw at them, so
  // they run here, without the child's copies through the pipe.
  if (reader == ModelReader::Any) {
    if (std::optional<Model> model = read_directly(path)) return std::move(*model);
  }
  check_ply_header(path);
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  try {
    Model model =
        deserialize(path, run_in_child_process([&] { return serialize(read_model(path)); },
                                               {.time = read_time_limit(ec ? 0 : size),
                                                .memory_bytes = read_memory_limit(ec ? 0 : size)}));
    for (const std::string& w : model.warnings) {
      std::fprintf(stderr, "penumbra: warning: %s\n", w.c_str());
    }
    return model;
  } catch (const ChildProcessError& e) {
    if (e.kind() == ChildProcessError::Kind::Threw) throw RuntimeError(e.what());
    // A file that needs more than the limit is hostile or broken: no
    // sound model of its size needs that much.
    fail(path, std::string("the model reader ") + e.what() + " on this file");
  }
}

void attach_model(Scene& scene, Shape& shape, const std::string& path, bool own_materials) {
  auto model = std::make_shared<const Model>(load_model(path));
  shape.kind = ShapeKind::Model;
  shape.file = path;
  shape.own_materials = own_materials;
  if (own_materials) {
    shape.material = static_cast<int>(scene.materials.size());
    scene.materials.insert(scene.materials.end(), model->materials.begin(), model->materials.end());
  }
  shape.model = std::move(model);
}

}  // namespace penumbra
