// The direct OBJ and binary PLY readers against the assimp path on small
// files: the same triangles with the same positions, normals, texture
// coordinates and colours, the same material; and their errors.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "model_files.hpp"
#include "penumbra/error.hpp"
#include "scene/model.hpp"

namespace penumbra {
namespace {

using testing::write_model_file;

// Corners as triangles list them: what a renderer draws, whatever the
// vertices' order or sharing. PLY floats are copied, so equal; OBJ
// decimals are parsed to the nearest float by std::from_chars, where
// assimp's parser can be one unit in the last place off (one coordinate
// in ten of the bunny's), so OBJ positions and normals may differ by that.
constexpr float kObjRounding = 1e-6f;
void expect_same_model(const std::string& path, float position_tolerance = 0.0f) {
  const Model direct = load_model(path);
  const Model assimp = load_model(path, ModelReader::Assimp);
  ASSERT_EQ(direct.mesh.indices.size(), assimp.mesh.indices.size()) << path;
  for (std::size_t i = 0; i < direct.mesh.indices.size(); ++i) {
    const Vertex& a = direct.mesh.vertices[direct.mesh.indices[i]];
    const Vertex& b = assimp.mesh.vertices[assimp.mesh.indices[i]];
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a.position[k], b.position[k], position_tolerance) << path << " corner " << i;
      EXPECT_NEAR(a.normal[k], b.normal[k], 1e-6f + 10.0f * position_tolerance)
          << path << " corner " << i;
    }
    EXPECT_EQ(a.uv, b.uv) << path << " corner " << i;
    EXPECT_EQ(a.color, b.color) << path << " corner " << i;
    EXPECT_EQ(a.material, b.material) << path << " corner " << i;
  }
  ASSERT_EQ(direct.materials.size(), assimp.materials.size());
  const Material& a = direct.materials[0];
  const Material& b = assimp.materials[0];
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.albedo, b.albedo);
  EXPECT_EQ(a.specular, b.specular);
  EXPECT_EQ(a.shininess, b.shininess);
  EXPECT_EQ(a.alpha, b.alpha);
  EXPECT_EQ(a.alpha_mode, b.alpha_mode);
  EXPECT_EQ(a.double_sided, b.double_sided);
  EXPECT_EQ(a.texture, nullptr);
  EXPECT_EQ(b.texture, nullptr);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(direct.bounds.min[k], assimp.bounds.min[k], position_tolerance);
    EXPECT_NEAR(direct.bounds.max[k], assimp.bounds.max[k], position_tolerance);
  }
}

// A bumpy 5 x 5 grid of quads (smooth normals where it bends gently, a
// crease where it folds) as OBJ lines.
std::string grid_positions() {
  std::string out;
  for (int j = 0; j <= 5; ++j) {
    for (int i = 0; i <= 5; ++i) {
      const float y = i < 3 ? 0.1f * static_cast<float>(j % 2) : 0.8f * static_cast<float>(i - 2);
      out += "v " + std::to_string(0.25f * i) + " " + std::to_string(y) + " " +
             std::to_string(0.25f * j) + "\n";
    }
  }
  return out;
}

TEST(DirectReader, ObjTrianglesEqualAssimp) {
  std::string obj = "# triangles, positions only\no grid\ng part\ns 1\n" + grid_positions();
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const int a = 1 + j * 6 + i, b = a + 1, c = a + 6, d = c + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
      obj += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(b) + "\n";
    }
  }
  expect_same_model(write_model_file("direct-tris.obj", obj), kObjRounding);
}

TEST(DirectReader, ObjQuadsWithNegativeIndicesEqualAssimp) {
  // Each quad's corners counted back from the last position.
  std::string obj = grid_positions();
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const int a = 1 + j * 6 + i - 37, b = a + 1, c = a + 6, d = c + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + " " +
             std::to_string(b) + "\n";
    }
  }
  expect_same_model(write_model_file("direct-quads.obj", obj), kObjRounding);
  EXPECT_EQ(load_model(write_model_file("direct-quads.obj", obj)).mesh.indices.size(), 150u);
}

TEST(DirectReader, ConcaveQuadSplitsAsAssimpSplitsIt) {
  // An arrowhead: corner 2 is concave, so the fan from corner 0 would
  // cover the notch.
  expect_same_model(
      write_model_file("direct-concave.obj", "v 0 0 0\nv 2 0 0\nv 1 0.5 0\nv 0 2 0\nf 1 2 3 4\n"),
      kObjRounding);
  const Model m = load_model(
      write_model_file("direct-concave.obj", "v 0 0 0\nv 2 0 0\nv 1 0.5 0\nv 0 2 0\nf 1 2 3 4\n"));
  ASSERT_EQ(m.mesh.indices.size(), 6u);
  // Every triangle faces +z (none folds over the notch).
  for (std::size_t t = 0; t < 6; t += 3) {
    const glm::vec3 a = m.mesh.vertices[m.mesh.indices[t]].position;
    const glm::vec3 b = m.mesh.vertices[m.mesh.indices[t + 1]].position;
    const glm::vec3 c = m.mesh.vertices[m.mesh.indices[t + 2]].position;
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f);
  }
}

TEST(DirectReader, ConvexPolygonIsAFan) {
  const Model m = load_model(write_model_file(
      "direct-pentagon.obj", "v 0 0 0\nv 2 0 0\nv 3 1 0\nv 1 3 0\nv -1 1 0\nf 1 2 3 4 5\n"));
  ASSERT_EQ(m.mesh.indices.size(), 9u);
  const std::vector<glm::vec3> expected = {{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {0, 0, 0}, {3, 1, 0},
                                           {1, 3, 0}, {0, 0, 0}, {1, 3, 0}, {-1, 1, 0}};
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_EQ(m.mesh.vertices[m.mesh.indices[i]].position, expected[i]) << i;
  }
}

TEST(DirectReader, ObjWithNormalsAndTextureCoordinatesEqualsAssimp) {
  std::string obj = grid_positions();
  for (int j = 0; j <= 5; ++j) {
    for (int i = 0; i <= 5; ++i) {
      obj += "vt " + std::to_string(0.2f * i) + " " + std::to_string(0.2f * j) + "\n";
      obj += "vn " + std::to_string(0.1f * i) + " 2 " + std::to_string(-0.1f * j) + "\n";
    }
  }
  obj += "vn 0 0 0\n";  // unusable: repaired from the faces around it
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const int a = 1 + j * 6 + i, b = a + 1, c = a + 6, d = c + 1;
      const auto corner = [&](int v) {
        const std::string n = v == 8 ? "37" : std::to_string(v);
        return std::to_string(v) + "/" + std::to_string(v) + "/" + n;
      };
      obj += "f " + corner(a) + " " + corner(c) + " " + corner(d) + " " + corner(b) + "\n";
    }
  }
  expect_same_model(write_model_file("direct-full.obj", obj), kObjRounding);
  // Texture coordinates without normals: normals computed.
  std::string uv_only = grid_positions();
  for (int j = 0; j <= 5; ++j) {
    for (int i = 0; i <= 5; ++i) {
      uv_only += "vt " + std::to_string(0.2f * i) + " " + std::to_string(0.2f * j) + "\n";
    }
  }
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const int a = 1 + j * 6 + i, b = a + 1, c = a + 6, d = c + 1;
      uv_only += "f " + std::to_string(a) + "/" + std::to_string(a) + " " + std::to_string(c) +
                 "/" + std::to_string(c) + " " + std::to_string(d) + "/" + std::to_string(d) + "\n";
      uv_only += "f " + std::to_string(a) + "/" + std::to_string(a) + " " + std::to_string(d) +
                 "/" + std::to_string(d) + " " + std::to_string(b) + "/" + std::to_string(b) + "\n";
    }
  }
  expect_same_model(write_model_file("direct-uv.obj", uv_only), kObjRounding);
}

// The test's own grid as a binary PLY with normals, texture coordinates,
// colours and a property the reader skips, its faces quads.
std::string grid_ply(bool normals, bool extras) {
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment made by the tests\n";
  header += "element vertex 36\nproperty float x\nproperty float y\nproperty float z\n";
  if (normals) header += "property float nx\nproperty float ny\nproperty float nz\n";
  if (extras) {
    header +=
        "property float confidence\nproperty float s\nproperty float t\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  }
  header += "element face 25\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body;
  const auto put = [&](const auto& value) {
    body.append(reinterpret_cast<const char*>(&value), sizeof value);
  };
  for (int j = 0; j <= 5; ++j) {
    for (int i = 0; i <= 5; ++i) {
      put(0.25f * i);
      put(i < 3 ? 0.1f * static_cast<float>(j % 2) : 0.8f * static_cast<float>(i - 2));
      put(0.25f * j);
      if (normals) {
        put(0.1f * i);
        put(j == 1 && i == 1 ? 0.0f : 2.0f);
        put(j == 1 && i == 1 ? 0.0f : -0.1f * j);
      }
      if (extras) {
        put(0.5f);
        put(0.2f * i);
        put(0.2f * j);
        put(static_cast<unsigned char>(40 * i));
        put(static_cast<unsigned char>(40 * j));
        put(static_cast<unsigned char>(200));
      }
    }
  }
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) {
      const std::int32_t a = j * 6 + i, b = a + 1, c = a + 6, d = c + 1;
      put(static_cast<unsigned char>(4));
      for (const std::int32_t v : {a, c, d, b}) put(v);
    }
  }
  return header + body;
}

TEST(DirectReader, BinaryPlyEqualsAssimp) {
  expect_same_model(write_model_file("direct-plain.ply", grid_ply(false, false)));
  expect_same_model(write_model_file("direct-normals.ply", grid_ply(true, false)));
  expect_same_model(write_model_file("direct-extras.ply", grid_ply(false, true)));
  expect_same_model(write_model_file("direct-all.ply", grid_ply(true, true)));
}

void expect_error(const std::string& name, const std::string& content, const std::string& what) {
  const std::string path = write_model_file(name, content);
  try {
    load_model(path);
    ADD_FAILURE() << name << " loaded";
  } catch (const RuntimeError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path + ": " + what, 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(DirectReader, MalformedObjLinesAreOneErrorNamingTheLine) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expect_error("bad-number.obj", "v 0 0 0\nv 1 x 0\nv 0 1 0\nf 1 2 3\n",
               "line 2: 'x' is not a number");
  expect_error("short-position.obj", "v 0 0\nf 1 1 1\n", "line 1: a position needs three numbers");
  expect_error("bad-index.obj", tri + "f 1 2 q\n", "line 4: 'q' is not a vertex index");
  expect_error("zero-index.obj", tri + "f 0 1 2\n",
               "line 4: position index 0 is out of range (the file has 3 positions");
  expect_error("far-back.obj", tri + "f -1 -2 -4\n",
               "line 4: position index -4 is out of range (the file has 3 positions");
  expect_error("no-uv.obj", tri + "f 1/1 2/1 3/1\n", "line 4: texture coordinate index 1 is out");
  expect_error("two-corners.obj", tri + "f 1 2\n", "line 4: a face needs at least three corners");
  expect_error("bad-corner.obj", tri + "f 1 2 3x\n", "line 4: a face corner is not");
  expect_error("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n",
               "mesh 0, vertex 1: position (1, nan, 0) is not finite");
  expect_error("only-groups.obj", tri + "g nothing\n", "the file holds no triangles");
}

TEST(DirectReader, MalformedBinaryPlyIsOneError) {
  const std::string ply = grid_ply(false, false);
  const std::size_t body = ply.find("end_header\n") + 11;
  expect_error("short.ply", ply.substr(0, body + 100), "the PLY header promises 36 vertices");
  std::string huge = ply;
  huge.replace(huge.find("vertex 36"), 9, "vertex 4000000000");
  expect_error("huge.ply", huge, "the PLY header promises 4000000000 vertices");
  std::string range = ply;
  const std::int32_t bad = 36;
  std::memcpy(range.data() + body + 36 * 12 + 1, &bad, sizeof bad);
  expect_error("range.ply", range,
               "mesh 0, face 0: vertex index 36 is out of range (the mesh has 36 vertices)");
  std::string nan = ply;
  const float not_a_number = std::nanf("");
  std::memcpy(nan.data() + body + 12 * 7 + 4, &not_a_number, sizeof not_a_number);
  expect_error("nan.ply", nan, "mesh 0, vertex 7: position (");
}

// Files the direct readers leave to assimp still load through it.
TEST(DirectReader, OtherFeaturesGoToAssimp) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  // A position with w, a line element, a non-convex pentagon.
  EXPECT_EQ(load_model(write_model_file("w.obj", "v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n"))
                .mesh.indices.size(),
            3u);
  EXPECT_EQ(load_model(write_model_file("line.obj", tri + "l 1 2\nf 1 2 3\n")).mesh.indices.size(),
            3u);
  const Model star = load_model(
      write_model_file("notch.obj", "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 1 0\nv 0 4 0\nf 1 2 3 4 5\n"));
  EXPECT_EQ(star.mesh.indices.size(), 9u);
  std::string ascii = grid_ply(false, false);
  ascii.replace(ascii.find("binary_little_endian"), 20, "binary_big_endian");
  EXPECT_THROW(load_model(write_model_file("big-endian.ply", ascii)), RuntimeError);
}

}  // namespace
}  // namespace penumbra
