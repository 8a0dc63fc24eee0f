#include "scene/mesh.hpp"

#include <charconv>
#include <cstdlib>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/display_name.hpp"
#include "penumbra/error.hpp"
#include "scene/model.hpp"

namespace penumbra {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Builds in object space; the caller transforms.
struct Builder {
  TriangleMesh local;
  std::uint32_t add(glm::vec3 p, glm::vec3 n) {
    local.vertices.push_back({p, n, 0, glm::vec2(0.0f), 0xffffffffu});
    return static_cast<std::uint32_t>(local.vertices.size() - 1);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    local.indices.insert(local.indices.end(), {a, b, c});
  }
  // Quad a-b-c-d counter-clockwise seen from the side the normal points to.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    triangle(a, b, c);
    triangle(a, c, d);
  }
  // A flat rectangle centred at `center` spanning u and v, facing u x v.
  void face(glm::vec3 center, glm::vec3 u, glm::vec3 v) {
    glm::vec3 n = glm::normalize(glm::cross(u, v));
    std::uint32_t a = add(center - u - v, n);
    std::uint32_t b = add(center + u - v, n);
    std::uint32_t c = add(center + u + v, n);
    std::uint32_t d = add(center - u + v, n);
    quad(a, b, c, d);
  }
};

void build_plane(Builder& b, const Shape& s) {
  // Subdivided so that per-vertex work (and light-space depth fitting) sees
  // the plane's interior, and large planes interpolate well.
  const int n = 8;
  const float hx = 0.5f * s.size.x, hz = 0.5f * s.size.z;
  const std::uint32_t base = static_cast<std::uint32_t>(b.local.vertices.size());
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      float x = -hx + 2.0f * hx * static_cast<float>(i) / n;
      float z = -hz + 2.0f * hz * static_cast<float>(j) / n;
      b.add({x, 0.0f, z}, {0.0f, 1.0f, 0.0f});
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      std::uint32_t a = base + static_cast<std::uint32_t>(j * (n + 1) + i);
      std::uint32_t c = a + static_cast<std::uint32_t>(n + 1);
      // Counter-clockwise seen from +y: (x, z+) comes before (x+, z).
      b.quad(a, c, c + 1, a + 1);
    }
  }
}

void build_box(Builder& b, const Shape& s) {
  glm::vec3 h = 0.5f * s.size;
  b.face({h.x, 0, 0}, {0, 0, -h.z}, {0, h.y, 0});
  b.face({-h.x, 0, 0}, {0, 0, h.z}, {0, h.y, 0});
  b.face({0, h.y, 0}, {h.x, 0, 0}, {0, 0, -h.z});
  b.face({0, -h.y, 0}, {h.x, 0, 0}, {0, 0, h.z});
  b.face({0, 0, h.z}, {h.x, 0, 0}, {0, h.y, 0});
  b.face({0, 0, -h.z}, {-h.x, 0, 0}, {0, h.y, 0});
}

void build_sphere(Builder& b, const Shape& s) {
  const int slices = kCurveSegments, stacks = kCurveSegments / 2;
  const std::uint32_t base = static_cast<std::uint32_t>(b.local.vertices.size());
  for (int j = 0; j <= stacks; ++j) {
    float theta = kPi * static_cast<float>(j) / stacks;
    for (int i = 0; i <= slices; ++i) {
      float phi = 2.0f * kPi * static_cast<float>(i) / slices;
      glm::vec3 n{std::sin(theta) * std::cos(phi), std::cos(theta),
                  -std::sin(theta) * std::sin(phi)};
      b.add(s.radius * n, n);
    }
  }
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      std::uint32_t a = base + static_cast<std::uint32_t>(j * (slices + 1) + i);
      std::uint32_t c = a + static_cast<std::uint32_t>(slices + 1);
      b.quad(a, c, c + 1, a + 1);
    }
  }
}

void build_cylinder(Builder& b, const Shape& s) {
  const int n = kCurveSegments;
  const float h = 0.5f * s.height;
  const std::uint32_t side = static_cast<std::uint32_t>(b.local.vertices.size());
  for (int i = 0; i <= n; ++i) {
    float phi = 2.0f * kPi * static_cast<float>(i) / n;
    glm::vec3 d{std::cos(phi), 0.0f, -std::sin(phi)};
    b.add(s.radius * d + glm::vec3(0, -h, 0), d);
    b.add(s.radius * d + glm::vec3(0, h, 0), d);
  }
  for (int i = 0; i < n; ++i) {
    std::uint32_t a = side + static_cast<std::uint32_t>(2 * i);
    b.quad(a, a + 2, a + 3, a + 1);
  }
  for (float y : {-h, h}) {
    glm::vec3 normal{0.0f, y > 0 ? 1.0f : -1.0f, 0.0f};
    std::uint32_t center = b.add({0.0f, y, 0.0f}, normal);
    std::uint32_t ring = static_cast<std::uint32_t>(b.local.vertices.size());
    for (int i = 0; i <= n; ++i) {
      float phi = 2.0f * kPi * static_cast<float>(i) / n;
      b.add({s.radius * std::cos(phi), y, -s.radius * std::sin(phi)}, normal);
    }
    for (int i = 0; i < n; ++i) {
      std::uint32_t r = ring + static_cast<std::uint32_t>(i);
      if (y > 0) {
        b.triangle(center, r, r + 1);
      } else {
        b.triangle(center, r + 1, r);
      }
    }
  }
}

void build_torus(Builder& b, const Shape& s) {
  const int rings = kCurveSegments, sides = kCurveSegments / 2;
  const std::uint32_t base = static_cast<std::uint32_t>(b.local.vertices.size());
  for (int j = 0; j <= rings; ++j) {
    float phi = 2.0f * kPi * static_cast<float>(j) / rings;
    glm::vec3 d{std::cos(phi), 0.0f, -std::sin(phi)};
    for (int i = 0; i <= sides; ++i) {
      float theta = 2.0f * kPi * static_cast<float>(i) / sides;
      glm::vec3 n = std::cos(theta) * d + glm::vec3(0.0f, std::sin(theta), 0.0f);
      b.add(s.radius * d + s.tube * n, n);
    }
  }
  for (int j = 0; j < rings; ++j) {
    for (int i = 0; i < sides; ++i) {
      std::uint32_t a = base + static_cast<std::uint32_t>(j * (sides + 1) + i);
      std::uint32_t c = a + static_cast<std::uint32_t>(sides + 1);
      b.quad(a, c, c + 1, a + 1);
    }
  }
}

}  // namespace

glm::mat4 shape_transform(const Shape& shape) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), shape.position);
  m = glm::rotate(m, glm::radians(shape.rotation_degrees.z), {0, 0, 1});
  m = glm::rotate(m, glm::radians(shape.rotation_degrees.y), {0, 1, 0});
  m = glm::rotate(m, glm::radians(shape.rotation_degrees.x), {1, 0, 0});
  return glm::scale(m, shape.scale);
}

namespace {

// Appends `local` transformed by the shape's placement. Vertex materials are
// the shape's, or offsets from it for a model with its own materials.
void append_transformed(TriangleMesh& mesh, const TriangleMesh& local, const Shape& shape,
                        bool material_offsets) {
  const glm::mat4 m = shape_transform(shape);
  // Normals transform by the inverse transpose, (R S)^-T = R S^-1; with a
  // scale of 1 this is the rotation exactly.
  const glm::vec3 inverse_square = 1.0f / (shape.scale * shape.scale);
  glm::mat3 normal_matrix = glm::mat3(m);
  for (int axis = 0; axis < 3; ++axis) normal_matrix[axis] *= inverse_square[axis];
  const std::uint32_t base = static_cast<std::uint32_t>(mesh.vertices.size());
  const auto material = static_cast<std::uint32_t>(shape.material);
  // Grow geometrically but at least once per shape: a million-triangle
  // model is copied in one allocation.
  const auto reserve = [](auto& v, std::size_t extra) {
    if (v.capacity() < v.size() + extra) v.reserve(std::max(v.size() + extra, 2 * v.capacity()));
  };
  reserve(mesh.vertices, local.vertices.size());
  reserve(mesh.indices, local.indices.size());
  for (const Vertex& v : local.vertices) {
    mesh.vertices.push_back({glm::vec3(m * glm::vec4(v.position, 1.0f)),
                             glm::normalize(normal_matrix * v.normal),
                             material_offsets ? material + v.material : material, v.uv, v.color});
  }
  for (std::uint32_t i : local.indices) mesh.indices.push_back(base + i);
}

}  // namespace

void append_shape(TriangleMesh& mesh, const Shape& shape) {
  if (shape.kind == ShapeKind::Model) {
    if (shape.model == nullptr) {
      throw std::invalid_argument("model shape '" + shape.file + "' was never loaded");
    }
    append_transformed(mesh, shape.model->mesh, shape, shape.own_materials);
    return;
  }
  Builder b;
  switch (shape.kind) {
    case ShapeKind::Plane:
      build_plane(b, shape);
      break;
    case ShapeKind::Box:
      build_box(b, shape);
      break;
    case ShapeKind::Sphere:
      build_sphere(b, shape);
      break;
    case ShapeKind::Cylinder:
      build_cylinder(b, shape);
      break;
    case ShapeKind::Torus:
      build_torus(b, shape);
      break;
    case ShapeKind::Model:
      break;  // above
  }
  append_transformed(mesh, b.local, shape, false);
}

std::size_t mesh_bytes(const TriangleMesh& mesh) {
  return mesh.vertices.size() * sizeof(Vertex) + mesh.indices.size() * sizeof(std::uint32_t);
}

std::size_t geometry_budget_bytes() {
  std::size_t megabytes = kDefaultGeometryBudgetMiB;
  if (const char* text = std::getenv(kGeometryBudgetVariable); text != nullptr && *text != '\0') {
    std::size_t value = 0;
    const char* end = text + std::strlen(text);
    const auto [ptr, ec] = std::from_chars(text, end, value);
    if (ec != std::errc() || ptr != end || value == 0 || value > (std::size_t{1} << 30)) {
      throw UsageError(std::string(kGeometryBudgetVariable) + "='" + text +
                       "' is not a number of MiB in [1, 2^30]");
    }
    megabytes = value;
  }
  return megabytes << 20;
}

TriangleMesh build_scene_mesh(const Scene& scene, std::vector<std::size_t>* first_vertex) {
  const std::size_t budget = geometry_budget_bytes();
  TriangleMesh mesh;
  if (first_vertex != nullptr) first_vertex->clear();
  for (std::size_t i = 0; i < scene.shapes.size(); ++i) {
    if (first_vertex != nullptr) first_vertex->push_back(mesh.vertices.size());
    append_shape(mesh, scene.shapes[i]);
    // Checked as the mesh grows, so that a scene far over the budget costs
    // no more memory than the budget to refuse.
    if (mesh_bytes(mesh) > budget ||
        mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max()) {
      throw UsageError(
          "scene " + display_name(scene.name) + ": its geometry exceeds the budget of " +
          std::to_string(budget >> 20) + " MiB at object " + std::to_string(i) + " of " +
          std::to_string(scene.shapes.size()) + " (" + std::to_string(mesh.indices.size() / 3) +
          " triangles, " + std::to_string(mesh_bytes(mesh) >> 20) + " MiB so far; " +
          kGeometryBudgetVariable + " sets the budget in MiB)");
    }
  }
  if (first_vertex != nullptr) first_vertex->push_back(mesh.vertices.size());
  return mesh;
}

Bounds TriangleMesh::bounds() const {
  Bounds b;
  for (const Vertex& v : vertices) b.extend(v.position);
  return b;
}

}  // namespace penumbra
