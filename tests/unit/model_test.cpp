// Models read through assimp: each format the tests write themselves, and
// every kind of broken file ending in one error that names it.
#include "scene/model.hpp"

#include <gtest/gtest.h>

#include <assimp/DefaultLogger.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "model_files.hpp"
#include "penumbra/error.hpp"

namespace penumbra {
namespace {

using testing::kTetrahedronHeight;
using testing::red_mtl;
using testing::tetrahedron_obj;
using testing::write_model_file;

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = 0;
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    for (std::size_t k = 0; k < 3; ++k) {
      chunk = (chunk << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    }
    for (std::size_t k = 0; k < 4; ++k) {
      out += k <= n ? digits[(chunk >> (18 - 6 * k)) & 63u] : '=';
    }
  }
  return out;
}

template <class T>
void append(std::string& bytes, const std::vector<T>& values) {
  const std::size_t start = bytes.size();
  bytes.resize(start + values.size() * sizeof(T));
  std::memcpy(bytes.data() + start, values.data(), values.size() * sizeof(T));
}

// A glTF 2.0 file with its buffer embedded as base64: the tetrahedron's
// positions and indices, a base colour, and a node that lifts it by 2.
std::string tetrahedron_gltf(const std::vector<float>& positions,
                             const std::vector<std::uint16_t>& indices) {
  std::string buffer;
  append(buffer, positions);
  append(buffer, indices);
  const std::size_t position_bytes = positions.size() * sizeof(float);
  return R"({
  "asset": {"version": "2.0"},
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0, "translation": [0, 2, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}],
  "buffers": [{"byteLength": )" +
         std::to_string(buffer.size()) + R"(, "uri": "data:application/octet-stream;base64,)" +
         base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )" +
         std::to_string(position_bytes) + R"(},
                  {"buffer": 0, "byteOffset": )" +
         std::to_string(position_bytes) + R"(, "byteLength": )" +
         std::to_string(indices.size() * 2) + R"(}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" +
         std::to_string(positions.size() / 3) + R"(, "type": "VEC3",
                 "min": [-1, 0, -1], "max": [1, 1, 1]},
                {"bufferView": 1, "componentType": 5123, "count": )" +
         std::to_string(indices.size()) + R"(, "type": "SCALAR"}]
})";
}

const std::vector<float> kTetrahedronPositions = {0.6f,  0.0f, 0.0f,  -0.3f, 0.0f, -0.52f,
                                                  -0.3f, 0.0f, 0.52f, 0.0f,  1.0f, 0.0f};
const std::vector<std::uint16_t> kTetrahedronIndices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};

void expect_bounds(const Model& m, glm::vec3 lo, glm::vec3 hi, float tolerance = 1e-4f) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(m.bounds.min[i], lo[i], tolerance) << "axis " << i;
    EXPECT_NEAR(m.bounds.max[i], hi[i], tolerance) << "axis " << i;
  }
}

// Every normal has unit length and points away from the centroid (the
// test models are convex).
void expect_outward_normals(const Model& m) {
  const glm::vec3 centre = m.bounds.center();
  for (std::size_t i = 0; i < m.mesh.indices.size(); i += 3) {
    const Vertex& a = m.mesh.vertices[m.mesh.indices[i]];
    const Vertex& b = m.mesh.vertices[m.mesh.indices[i + 1]];
    const Vertex& c = m.mesh.vertices[m.mesh.indices[i + 2]];
    const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
    EXPECT_GT(glm::dot(face, (a.position + b.position + c.position) / 3.0f - centre), 0.0f)
        << "triangle " << i / 3 << " winds inwards";
    for (const Vertex* v : {&a, &b, &c}) EXPECT_NEAR(glm::length(v->normal), 1.0f, 1e-4f);
  }
}

TEST(Model, ReadsObjWithItsMaterial) {
  write_model_file("tet-red.mtl", red_mtl());
  const Model m = load_model(write_model_file("tet-red.obj", tetrahedron_obj("tet-red.mtl")));
  EXPECT_EQ(m.mesh.indices.size(), 12u);
  // The file has no normals: faces meeting at 109 degrees are not smoothed.
  EXPECT_EQ(m.mesh.vertices.size(), 12u);
  expect_bounds(m, {-0.3f, 0.0f, -0.5196f}, {0.6f, kTetrahedronHeight, 0.5196f});
  expect_outward_normals(m);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_NEAR(m.materials[0].albedo.r, 0.8f, 1e-6f);
  EXPECT_NEAR(m.materials[0].albedo.g, 0.1f, 1e-6f);
  EXPECT_NEAR(m.materials[0].specular.r, 0.5f, 1e-6f);
  EXPECT_NEAR(m.materials[0].shininess, 50.0f, 1e-4f);
  for (const Vertex& v : m.mesh.vertices) EXPECT_EQ(v.material, 0u);
}

TEST(Model, ReadsAsciiPly) {
  const Model m = load_model(write_model_file("tet.ply", R"(ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 4
property list uchar int vertex_indices
end_header
0.6 0 0
-0.3 0 -0.52
-0.3 0 0.52
0 1 0
3 0 2 1
3 0 1 3
3 1 2 3
3 2 0 3
)"));
  EXPECT_EQ(m.mesh.indices.size(), 12u);
  expect_bounds(m, {-0.3f, 0.0f, -0.52f}, {0.6f, 1.0f, 0.52f});
  expect_outward_normals(m);
  EXPECT_EQ(m.materials.size(), 1u);
}

TEST(Model, ReadsGltfWithEmbeddedBufferAndNodeTransform) {
  const Model m = load_model(
      write_model_file("tet.gltf", tetrahedron_gltf(kTetrahedronPositions, kTetrahedronIndices)));
  EXPECT_EQ(m.mesh.indices.size(), 12u);
  // The node's translation is applied.
  expect_bounds(m, {-0.3f, 2.0f, -0.52f}, {0.6f, 3.0f, 0.52f});
  expect_outward_normals(m);
  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_NEAR(m.materials[0].albedo.r, 0.2f, 1e-6f);
  EXPECT_NEAR(m.materials[0].albedo.g, 0.4f, 1e-6f);
  EXPECT_NEAR(m.materials[0].albedo.b, 0.6f, 1e-6f);
}

TEST(Model, ReadsAsciiStl) {
  // Two facets of a unit square in the x-z plane, facing up.
  const Model m = load_model(write_model_file("square.stl", R"(solid square
facet normal 0 1 0
 outer loop
  vertex 0 0 0
  vertex 0 0 1
  vertex 1 0 0
 endloop
endfacet
facet normal 0 1 0
 outer loop
  vertex 1 0 0
  vertex 0 0 1
  vertex 1 0 1
 endloop
endfacet
endsolid square
)"));
  EXPECT_EQ(m.mesh.indices.size(), 6u);
  expect_bounds(m, {0.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 1.0f});
  for (const Vertex& v : m.mesh.vertices) EXPECT_NEAR(v.normal.y, 1.0f, 1e-6f);
}

TEST(Model, ReadsOffWithQuadsSplit) {
  // A cube of side 2 made of six quads: 12 triangles once triangulated.
  const Model m = load_model(write_model_file("cube.off", testing::cube_off()));
  EXPECT_EQ(m.mesh.indices.size(), 36u);
  expect_bounds(m, glm::vec3(-1.0f), glm::vec3(1.0f));
  expect_outward_normals(m);
}

// The message starts with the path and is one line.
void expect_model_error(const std::string& path, const std::string& expected) {
  try {
    load_model(path);
    ADD_FAILURE() << path << " loaded";
  } catch (const RuntimeError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(ModelErrors, MissingFileFolderOrDevice) {
  expect_model_error(write_model_file("placeholder.txt", "") + ".missing.obj", "no such file");
  expect_model_error(std::string(PENUMBRA_TEST_OUTPUT) + "/models", "folder");
  expect_model_error("/dev/null", "not a regular file");
}

TEST(ModelErrors, GarbageBytes) {
  std::string garbage;
  std::uint32_t state = 12345u;
  for (int i = 0; i < 4096; ++i) {
    state = state * 1664525u + 1013904223u;
    garbage += static_cast<char>(state >> 24);
  }
  for (const char* name : {"garbage.obj", "garbage.ply", "garbage.glb", "garbage.stl",
                           "garbage.off", "garbage.gltf", "garbage.xyz"}) {
    expect_model_error(write_model_file(name, garbage), "");
  }
}

TEST(ModelErrors, TruncatedFiles) {
  // A binary STL: 80-byte header, a count of 1000 triangles, the data of 10.
  std::string stl(80, ' ');
  append(stl, std::vector<std::uint32_t>{1000u});
  stl.resize(stl.size() + 10 * 50, '\0');
  expect_model_error(write_model_file("truncated.stl", stl), "");

  const std::string gltf = tetrahedron_gltf(kTetrahedronPositions, kTetrahedronIndices);
  expect_model_error(write_model_file("truncated.gltf", gltf.substr(0, gltf.size() / 2)), "");

  const std::string obj = tetrahedron_obj();
  expect_model_error(write_model_file("truncated.obj", obj.substr(0, obj.find("f 2 3 4") + 5)), "");
}

TEST(ModelErrors, PlyHeaderWithoutItsEnd) {
  // Without end_header assimp's PLY reader never returns: the file is
  // refused first, whatever its name.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  expect_model_error(write_model_file("no-end-header.ply", ply), "end_header");
  expect_model_error(write_model_file("no-end-header.model", ply), "end_header");
}

TEST(ModelErrors, AReaderThatCrashesIsAnError) {
  // Found by fuzzing: assimp 5.2's OFF reader crashes on this file. The
  // reader runs in a child process, so the load ends in an error naming
  // the file (or, with a reader that survives it, loads or refuses it).
  const std::string off =
      "OFF\n3 1 0\n0 0 0F\n3 1 0 0 1\x19"
      "1 \x83 0\n0 1 0\n \xd8"
      "0  32\n\x0e&";
  const std::string path = write_model_file("reader-crash.off", off);
  try {
    load_model(path);
  } catch (const RuntimeError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
  }
}

TEST(ModelErrors, NoTriangles) {
  expect_model_error(write_model_file("empty.obj", ""), "empty");
  expect_model_error(write_model_file("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "no triangles");
  expect_model_error(write_model_file("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"),
                     "no triangles");
  expect_model_error(write_model_file("comment.obj", "# nothing here\n"), "");
  expect_model_error(write_model_file("garbage-text.obj", "hello world\nthis is not a model\n"),
                     "no triangles");
}

TEST(ModelErrors, IndexOutOfRange) {
  expect_model_error(write_model_file("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n"),
                     "out of range");
  expect_model_error(write_model_file("range.ply", R"(ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
element face 1
property list uchar int vertex_indices
end_header
0 0 0
1 0 0
0 1 0
3 0 1 99
)"),
                     "out of range");
  std::vector<std::uint16_t> indices = kTetrahedronIndices;
  indices[4] = 99;
  // Assimp drops such faces with a warning only; it must still fail.
  expect_model_error(
      write_model_file("range.gltf", tetrahedron_gltf(kTetrahedronPositions, indices)),
      "out-of-range");
}

// A program that made assimp's logger keeps it, and the check still works.
TEST(ModelErrors, DroppedDataIsFoundWithTheProgramsOwnLogger) {
  Assimp::DefaultLogger::create(nullptr, Assimp::Logger::NORMAL, 0);
  Assimp::Logger* program_logger = Assimp::DefaultLogger::get();
  std::vector<std::uint16_t> indices = kTetrahedronIndices;
  indices[7] = 1000;
  expect_model_error(
      write_model_file("range-logger.gltf", tetrahedron_gltf(kTetrahedronPositions, indices)),
      "out-of-range");
  EXPECT_EQ(Assimp::DefaultLogger::get(), program_logger);
  EXPECT_FALSE(Assimp::DefaultLogger::isNullLogger());
  Assimp::DefaultLogger::kill();
}

TEST(ModelErrors, NonFinitePositions) {
  expect_model_error(write_model_file("nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                     "not finite");
  expect_model_error(write_model_file("inf.obj", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n"),
                     "not finite");
  std::vector<float> positions = kTetrahedronPositions;
  positions[4] = std::nanf("");
  expect_model_error(write_model_file("nan.gltf", tetrahedron_gltf(positions, kTetrahedronIndices)),
                     "not finite");
}

}  // namespace
}  // namespace penumbra
