// The direct OBJ reader (direct_readers.hpp). Two passes over the file: the
// first counts the v, vt, vn and f lines (and finds a keyword this reader
// leaves to assimp before any work), the second parses numbers with
// std::from_chars into arrays reserved from those counts.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

#include "io/buffered_file.hpp"
#include "penumbra/error.hpp"
#include "scene/direct_readers.hpp"
#include "scene/face_triangulation.hpp"

namespace penumbra {

namespace {

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// Calls line(text) for each line, without its line feed.
template <class Line>
void for_each_line(const std::string& path, Line&& line) {
  BufferedFile file(path);
  for (std::string_view chunk = file.lines(); !chunk.empty(); chunk = file.lines()) {
    while (!chunk.empty()) {
      const std::size_t end = chunk.find('\n');
      if (end == std::string_view::npos) {
        line(chunk);
        break;
      }
      line(chunk.substr(0, end));
      chunk.remove_prefix(end + 1);
    }
  }
}

std::string quoted(const char* begin, const char* end) {
  std::string out = "'";
  out.append(begin, end);
  out += '\'';
  return out;
}

// The line's first word (the keyword), after leading blanks.
std::string_view keyword(std::string_view line) {
  std::size_t begin = 0;
  while (begin < line.size() && blank(line[begin])) ++begin;
  std::size_t end = begin;
  while (end < line.size() && !blank(line[end])) ++end;
  return line.substr(begin, end - begin);
}

struct Counts {
  std::size_t positions = 0, uvs = 0, normals = 0, faces = 0;
};

// Open addressing from a corner's (position, uv, normal) indices to its
// vertex, so corners that share all three share a vertex.
class CornerTable {
 public:
  explicit CornerTable(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    slots_.assign(capacity, Slot{});
  }
  // The vertex of the key, or kNone after making room for a new one
  // (whose number the caller then gives with set).
  std::uint32_t find(std::uint32_t p, std::uint32_t t, std::uint32_t n) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    std::size_t i = hash(p, t, n) & (slots_.size() - 1);
    while (slots_[i].vertex != kNone) {
      const Slot& s = slots_[i];
      if (s.p == p && s.t == t && s.n == n) return s.vertex;
      i = (i + 1) & (slots_.size() - 1);
    }
    last_ = i;
    return kNone;
  }
  void set(std::uint32_t p, std::uint32_t t, std::uint32_t n, std::uint32_t vertex) {
    slots_[last_] = {p, t, n, vertex};
    ++size_;
  }
  static constexpr std::uint32_t kNone = 0xffffffffu;

 private:
  struct Slot {
    std::uint32_t p = 0, t = 0, n = 0, vertex = kNone;
  };
  static std::size_t hash(std::uint32_t p, std::uint32_t t, std::uint32_t n) {
    std::uint64_t h = p * 0x9e3779b97f4a7c15ull;
    h ^= (t + 0x632be59bd9b4e019ull) * 0xc2b2ae3d27d4eb4full;
    h ^= (n + 0x165667b19e3779f9ull) * 0x85ebca77c2b2ae63ull;
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
  void grow() {
    std::vector<Slot> old(slots_.size() * 2);
    old.swap(slots_);
    for (const Slot& s : old) {
      if (s.vertex == kNone) continue;
      std::size_t i = hash(s.p, s.t, s.n) & (slots_.size() - 1);
      while (slots_[i].vertex != kNone) i = (i + 1) & (slots_.size() - 1);
      slots_[i] = s;
    }
  }
  std::vector<Slot> slots_;
  std::size_t size_ = 0, last_ = 0;
};

// Why the reader stops without an error: the file needs assimp.
struct NeedsAssimp {};

class ObjParser {
 public:
  ObjParser(const std::string& path, const Counts& counts) : path_(path) {
    // Without texture coordinates and normals a vertex is a position: v
    // lines go straight into the vertex array and faces index it.
    plain_ = counts.uvs == 0 && counts.normals == 0;
    if (plain_) {
      out_.mesh.vertices.reserve(counts.positions);
    } else {
      positions_.reserve(counts.positions);
      uvs_.reserve(counts.uvs);
      normals_.reserve(counts.normals);
      corners_.emplace(counts.positions);
      out_.mesh.vertices.reserve(counts.positions);
    }
    out_.mesh.indices.reserve(3 * counts.faces);
  }

  void line(std::string_view text) {
    ++line_number_;
    const std::string_view word = keyword(text);
    const char* p = word.data() + word.size();
    const char* end = text.data() + text.size();
    if (word == "v") {
      glm::vec3 v;
      const int n = numbers(p, end, &v.x, 3);
      if (n != 3) {
        if (n > 3) throw NeedsAssimp{};  // w, or vertex colours
        fail("a position needs three numbers");
      }
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        std::ostringstream what;
        what << "mesh 0, vertex " << position_count() << ": position (" << v.x << ", " << v.y
             << ", " << v.z << ") is not finite";
        throw RuntimeError(path_ + ": " + what.str());
      }
      if (plain_) {
        out_.mesh.vertices.push_back({v, glm::vec3(0.0f), 0u});
      } else {
        positions_.push_back(v);
      }
    } else if (word == "vt") {
      float uvw[3] = {0.0f, 0.0f, 0.0f};
      const int n = numbers(p, end, uvw, 3);
      if (n < 2 || n > 3) throw NeedsAssimp{};
      // As the assimp path: a coordinate that is not finite becomes (0, 0).
      const bool finite = std::isfinite(uvw[0]) && std::isfinite(uvw[1]);
      uvs_.push_back(finite ? glm::vec2(uvw[0], uvw[1]) : glm::vec2(0.0f));
    } else if (word == "vn") {
      glm::vec3 v;
      if (numbers(p, end, &v.x, 3) != 3) fail("a normal needs three numbers");
      normals_.push_back(v);
    } else if (word == "f") {
      face(p, end);
    }
    // g, o, s and comments: nothing to keep (the first pass refused the rest).
  }

  DirectMesh finish() && {
    if (out_.mesh.indices.empty()) throw RuntimeError(path_ + ": the file holds no triangles");
    out_.has_normals = !plain_ && (shape_ & kNormal) != 0;
    return std::move(out_);
  }

 private:
  static constexpr int kUv = 1, kNormal = 2;

  [[noreturn]] void fail(const std::string& what) const {
    throw RuntimeError(path_ + ": line " + std::to_string(line_number_) + ": " + what);
  }

  std::size_t position_count() const {
    return plain_ ? out_.mesh.vertices.size() : positions_.size();
  }

  // The float a decimal [p, next) that from_chars found out of float's
  // range stands for: a magnitude too small for a float (below about
  // 1.4e-45) reads as a signed zero, as assimp and strtof read it; one too
  // large is infinite, and is refused as not finite.
  static float out_of_float_range(const char* p, const char* next) {
    const bool negative = *p == '-';
    double value = 0.0;
    const auto [ignored, error] = std::from_chars(p, next, value);
    if (error == std::errc() && std::abs(value) <= std::numeric_limits<float>::max()) {
      return static_cast<float>(value);  // a denormal, or zero
    }
    // Beyond double's range too: its exponent's sign says which way.
    const std::string_view text(p, static_cast<std::size_t>(next - p));
    const bool tiny =
        text.find("e-") != std::string_view::npos || text.find("E-") != std::string_view::npos;
    const float magnitude = tiny ? 0.0f : std::numeric_limits<float>::infinity();
    return negative ? -magnitude : magnitude;
  }

  // Up to `max` numbers from p to the end of the line into out; returns how
  // many the line has (more than max: max + 1). A word that is not a
  // number fails.
  int numbers(const char* p, const char* end, float* out, int max) const {
    int n = 0;
    for (;;) {
      while (p < end && blank(*p)) ++p;
      if (p == end || *p == '#') return n;
      if (n == max) return max + 1;
      if (*p == '+') ++p;
      const auto [next, error] = std::from_chars(p, end, out[n]);
      if (error == std::errc::result_out_of_range) {
        out[n] = out_of_float_range(p, next);
      } else if (error != std::errc() || (next < end && !blank(*next))) {
        const char* word_end = p;
        while (word_end < end && !blank(*word_end)) ++word_end;
        fail(quoted(p, word_end) + " is not a number");
      }
      p = next;
      ++n;
    }
  }

  // One index of a corner: 1-based, or negative counting back from the
  // last defined; returns it 0-based.
  std::uint32_t index(const char*& p, const char* end, std::size_t defined,
                      const char* what) const {
    long long k = 0;
    const auto [next, error] = std::from_chars(p, end, k);
    if (error != std::errc()) {
      const char* word_end = p;
      while (word_end < end && !blank(*word_end)) ++word_end;
      fail(quoted(p, word_end) + " is not a vertex index");
    }
    p = next;
    const long long resolved = k < 0 ? static_cast<long long>(defined) + k : k - 1;
    if (k == 0 || resolved < 0 || resolved >= static_cast<long long>(defined)) {
      std::ostringstream message;
      message << what << " index " << k << " is out of range (the file has " << defined << " "
              << what << "s before this line)";
      fail(message.str());
    }
    return static_cast<std::uint32_t>(resolved);
  }

  void face(const char* p, const char* end) {
    face_.clear();
    for (;;) {
      while (p < end && blank(*p)) ++p;
      if (p == end || *p == '#') break;
      const std::uint32_t v = index(p, end, position_count(), "position");
      std::uint32_t t = 0, n = 0;
      int shape = 0;
      if (p < end && *p == '/') {
        ++p;
        if (p < end && *p != '/' && !blank(*p)) {
          t = index(p, end, uvs_.size(), "texture coordinate");
          shape |= kUv;
        }
        if (p < end && *p == '/') {
          ++p;
          n = index(p, end, normals_.size(), "normal");
          shape |= kNormal;
        }
      }
      if (p < end && !blank(*p)) fail("a face corner is not v, v/vt, v//vn or v/vt/vn");
      // Corners that differ in what they have are left to assimp.
      if (shape_ < 0) shape_ = shape;
      if (shape != shape_) throw NeedsAssimp{};
      if (plain_) {
        face_.push_back(v);
      } else {
        std::uint32_t vertex = corners_->find(v, t, n);
        if (vertex == CornerTable::kNone) {
          vertex = static_cast<std::uint32_t>(out_.mesh.vertices.size());
          corners_->set(v, t, n, vertex);
          out_.mesh.vertices.push_back({positions_[v],
                                        (shape & kNormal) ? normals_[n] : glm::vec3(0.0f), 0u,
                                        (shape & kUv) ? uvs_[t] : glm::vec2(0.0f)});
        }
        face_.push_back(vertex);
      }
    }
    if (face_.size() < 3) fail("a face needs at least three corners");
    if (!append_face_triangles(face_, out_.mesh.vertices, out_.mesh.indices)) throw NeedsAssimp{};
  }

  std::string path_;
  bool plain_ = true;
  int shape_ = -1;  // kUv | kNormal of every corner, once the first is read
  std::size_t line_number_ = 0;
  std::vector<glm::vec3> positions_, normals_;
  std::vector<glm::vec2> uvs_;
  std::optional<CornerTable> corners_;
  std::vector<std::uint32_t> face_;
  DirectMesh out_;
};

}  // namespace

std::optional<DirectMesh> read_obj_directly(const std::string& path) {
  Counts counts;
  bool other = false;
  for_each_line(path, [&](std::string_view line) {
    if (other) return;
    const std::string_view word = keyword(line);
    if (word == "v") {
      ++counts.positions;
    } else if (word == "vt") {
      ++counts.uvs;
    } else if (word == "vn") {
      ++counts.normals;
    } else if (word == "f") {
      ++counts.faces;
    } else if (!(word.empty() || word[0] == '#' || word == "g" || word == "o" || word == "s")) {
      other = true;  // materials, lines, points, curves, or not OBJ at all
    }
    if (!line.empty() && line.back() == '\\') other = true;  // a continued line
  });
  if (other) return std::nullopt;
  if (counts.positions > 0xffffffffu) {
    throw RuntimeError(path + ": has more vertices than 32-bit indices reach");
  }
  try {
    ObjParser parser(path, counts);
    for_each_line(path, [&](std::string_view line) { parser.line(line); });
    return std::move(parser).finish();
  } catch (const NeedsAssimp&) {
    return std::nullopt;
  }
}

}  // namespace penumbra
