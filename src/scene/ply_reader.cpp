// The direct binary PLY reader (direct_readers.hpp). The header says how
// many vertices and faces follow and how each is laid out; both are read
// through a fixed buffer straight into the vertex and index arrays.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

#include "io/buffered_file.hpp"
#include "penumbra/error.hpp"
#include "scene/direct_readers.hpp"
#include "scene/face_triangulation.hpp"
#include "scene/texture.hpp"

namespace penumbra {

namespace {

struct NeedsAssimp {};

// The longest header line read (a comment, in practice).
constexpr std::size_t kMaxHeaderLine = std::size_t{1} << 20;

// Bytes of a PLY scalar type, 0 for an unknown name.
std::size_t type_size(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
}
bool is_float(const std::string& type) {
  return type == "float" || type == "float32";
}
bool is_uchar(const std::string& type) {
  return type == "uchar" || type == "uint8";
}

// Where each vertex attribute sits in a vertex record (-1: absent).
struct VertexLayout {
  std::size_t stride = 0;
  int position[3] = {-1, -1, -1};
  int normal[3] = {-1, -1, -1};
  int uv[2] = {-1, -1};
  int color[4] = {-1, -1, -1, -1};
};

struct FaceLayout {
  std::size_t count_size = 0;
  std::size_t index_size = 0;
  bool index_signed = false;
};

struct Header {
  std::uint64_t vertices = 0, faces = 0;
  VertexLayout vertex;
  FaceLayout face;
};

// Reads the header, or throws NeedsAssimp for a file this reader leaves to assimp.
Header read_header(const std::string& path, BufferedFile& file) {
  int number = 0;
  const auto line = [&] {
    std::string text;
    ++number;
    for (;;) {
      const char* c = file.take(1);
      if (c == nullptr) throw NeedsAssimp{};  // no end_header: assimp's error
      if (*c == '\n') break;
      text += *c;
      // Said here: assimp would call it a header without end_header.
      if (text.size() > kMaxHeaderLine) {
        throw RuntimeError(path + ": header line " + std::to_string(number) +
                           " is longer than 1 MiB");
      }
    }
    if (!text.empty() && text.back() == '\r') text.pop_back();
    return text;
  };
  if (line() != "ply") throw NeedsAssimp{};
  Header h;
  enum class Element { None, Vertex, Face } element = Element::None;
  bool format = false, seen_vertex = false, seen_face = false;
  for (;;) {
    std::istringstream words(line());
    std::string word;
    words >> word;
    if (word == "end_header") break;
    if (word == "comment" || word == "obj_info" || word.empty()) continue;
    if (word == "format") {
      std::string kind, version;
      words >> kind >> version;
      if (kind != "binary_little_endian" || version != "1.0") throw NeedsAssimp{};
      format = true;
    } else if (word == "element") {
      std::string name;
      std::uint64_t count = 0;
      if (!(words >> name >> count)) throw NeedsAssimp{};
      if (name == "vertex" && !seen_vertex && !seen_face) {
        element = Element::Vertex;
        seen_vertex = true;
        h.vertices = count;
      } else if (name == "face" && seen_vertex && !seen_face) {
        element = Element::Face;
        seen_face = true;
        h.faces = count;
      } else {
        throw NeedsAssimp{};  // edges, materials, ...
      }
    } else if (word == "property") {
      std::string type, name;
      if (!(words >> type)) throw NeedsAssimp{};
      if (type == "list") {
        std::string count_type, index_type;
        if (!(words >> count_type >> index_type >> name) || element != Element::Face ||
            h.face.count_size != 0 || (name != "vertex_indices" && name != "vertex_index")) {
          throw NeedsAssimp{};
        }
        h.face.count_size = type_size(count_type);
        h.face.index_size = type_size(index_type);
        h.face.index_signed = index_type == "int" || index_type == "int32";
        if (h.face.count_size == 0 || h.face.count_size > 4 ||
            (h.face.index_size != 4 && h.face.index_size != 2) || is_float(count_type) ||
            is_float(index_type)) {
          throw NeedsAssimp{};
        }
        continue;
      }
      if (!(words >> name) || element != Element::Vertex || type_size(type) == 0) {
        throw NeedsAssimp{};
      }
      VertexLayout& v = h.vertex;
      const int at = static_cast<int>(v.stride);
      v.stride += type_size(type);
      const auto set = [&](int& slot, bool type_ok) {
        if (!type_ok || slot >= 0) throw NeedsAssimp{};
        slot = at;
      };
      if (name == "x")
        set(v.position[0], is_float(type));
      else if (name == "y")
        set(v.position[1], is_float(type));
      else if (name == "z")
        set(v.position[2], is_float(type));
      else if (name == "nx")
        set(v.normal[0], is_float(type));
      else if (name == "ny")
        set(v.normal[1], is_float(type));
      else if (name == "nz")
        set(v.normal[2], is_float(type));
      else if (name == "u" || name == "s" || name == "texture_u" || name == "texture_s")
        set(v.uv[0], is_float(type));
      else if (name == "v" || name == "t" || name == "texture_v" || name == "texture_t")
        set(v.uv[1], is_float(type));
      else if (name == "red")
        set(v.color[0], is_uchar(type));
      else if (name == "green")
        set(v.color[1], is_uchar(type));
      else if (name == "blue")
        set(v.color[2], is_uchar(type));
      else if (name == "alpha")
        set(v.color[3], is_uchar(type));
      // Any other scalar (a scanner's confidence, intensity) is skipped, as assimp skips it.
    } else {
      throw NeedsAssimp{};
    }
  }
  const VertexLayout& v = h.vertex;
  const auto all_or_none = [](const int* slots, int n) {
    int present = 0;
    for (int i = 0; i < n; ++i) present += slots[i] >= 0;
    return present == 0 || present == n;
  };
  if (!format || !seen_vertex || !seen_face || h.face.count_size == 0 || v.position[0] < 0 ||
      v.position[1] < 0 || v.position[2] < 0 || !all_or_none(v.normal, 3) ||
      !all_or_none(v.uv, 2) || !all_or_none(v.color, 3)) {
    throw NeedsAssimp{};
  }
  return h;
}

float float_at(const char* record, int offset) {
  float f;
  std::memcpy(&f, record + offset, sizeof f);
  return f;
}

std::uint64_t unsigned_at(const char* p, std::size_t size) {
  std::uint8_t b[8] = {};
  std::memcpy(b, p, size);
  std::uint64_t value = 0;
  for (std::size_t i = size; i-- > 0;) value = value << 8 | b[i];
  return value;
}

DirectMesh read_body(const std::string& path, BufferedFile& file, const Header& h) {
  const auto fail = [&](const std::string& what) -> void {
    throw RuntimeError(path + ": " + what);
  };
  const VertexLayout& layout = h.vertex;
  // The counts must fit in what is left of the file before anything is
  // allocated for them (a 300-byte header can promise billions).
  const std::uint64_t left = file.left();
  if (h.vertices > left / layout.stride ||
      h.faces > (left - h.vertices * layout.stride) / h.face.count_size) {
    fail("the PLY header promises " + std::to_string(h.vertices) + " vertices and " +
         std::to_string(h.faces) + " faces, more than the file's " + std::to_string(left) +
         " bytes of data hold");
  }
  if (h.vertices > 0xffffffffu) fail("has more vertices than 32-bit indices reach");
  DirectMesh out;
  out.has_normals = layout.normal[0] >= 0;
  out.has_colors = layout.color[0] >= 0;
  TriangleMesh& mesh = out.mesh;
  mesh.vertices.resize(h.vertices);
  mesh.indices.reserve(3 * h.faces);

  const std::size_t batch = std::max<std::size_t>(1, (std::size_t{1} << 20) / layout.stride);
  for (std::size_t first = 0; first < h.vertices; first += batch) {
    const std::size_t count = std::min<std::size_t>(batch, h.vertices - first);
    const char* record = file.take(count * layout.stride);
    if (record == nullptr) fail("the file ends within its vertices");
    for (std::size_t i = 0; i < count; ++i, record += layout.stride) {
      Vertex& v = mesh.vertices[first + i];
      v.position = {float_at(record, layout.position[0]), float_at(record, layout.position[1]),
                    float_at(record, layout.position[2])};
      if (!std::isfinite(v.position.x) || !std::isfinite(v.position.y) ||
          !std::isfinite(v.position.z)) {
        std::ostringstream what;
        what << "mesh 0, vertex " << first + i << ": position (" << v.position.x << ", "
             << v.position.y << ", " << v.position.z << ") is not finite";
        fail(what.str());
      }
      if (out.has_normals) {
        v.normal = {float_at(record, layout.normal[0]), float_at(record, layout.normal[1]),
                    float_at(record, layout.normal[2])};
      }
      if (layout.uv[0] >= 0) {
        v.uv = {float_at(record, layout.uv[0]), float_at(record, layout.uv[1])};
        if (!std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) v.uv = glm::vec2(0.0f);
      }
      if (out.has_colors) {
        const auto channel = [&](int slot) {
          return slot < 0 ? 1.0f : static_cast<unsigned char>(record[slot]) / 255.0f;
        };
        v.color = pack_color({channel(layout.color[0]), channel(layout.color[1]),
                              channel(layout.color[2]), channel(layout.color[3])});
      }
    }
  }

  std::vector<std::uint32_t> corners;
  for (std::uint64_t f = 0; f < h.faces; ++f) {
    const char* count_bytes = file.take(h.face.count_size);
    if (count_bytes == nullptr) fail("the file ends within its faces");
    const std::uint64_t n = unsigned_at(count_bytes, h.face.count_size);
    if (n < 3) throw NeedsAssimp{};  // points and lines
    if (n > (1u << 16))
      fail("face " + std::to_string(f) + " has " + std::to_string(n) + " corners");
    const char* p = file.take(n * h.face.index_size);
    if (p == nullptr) fail("the file ends within its faces");
    corners.clear();
    for (std::uint64_t k = 0; k < n; ++k, p += h.face.index_size) {
      std::int64_t index = static_cast<std::int64_t>(unsigned_at(p, h.face.index_size));
      if (h.face.index_signed && h.face.index_size == 4) index = static_cast<std::int32_t>(index);
      if (index < 0 || static_cast<std::uint64_t>(index) >= h.vertices) {
        fail("mesh 0, face " + std::to_string(f) + ": vertex index " + std::to_string(index) +
             " is out of range (the mesh has " + std::to_string(h.vertices) + " vertices)");
      }
      corners.push_back(static_cast<std::uint32_t>(index));
    }
    if (!append_face_triangles(corners, mesh.vertices, mesh.indices)) throw NeedsAssimp{};
  }
  if (mesh.indices.empty()) fail("the file holds no triangles");
  return out;
}

}  // namespace

std::optional<DirectMesh> read_ply_directly(const std::string& path) {
  BufferedFile file(path);
  try {
    const Header header = read_header(path, file);
    return read_body(path, file, header);
  } catch (const NeedsAssimp&) {
    return std::nullopt;
  }
}

}  // namespace penumbra
