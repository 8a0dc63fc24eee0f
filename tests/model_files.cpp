#include "model_files.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <vector>

namespace penumbra::testing {

namespace fs = std::filesystem;

std::string write_model_file(const std::string& name, const std::string& content) {
  const fs::path path = fs::path(PENUMBRA_TEST_OUTPUT) / "models" / name;
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  return path.string();
}

std::string tetrahedron_obj(const std::string& material_file) {
  // Base: an equilateral triangle of circumradius r at y = 0; apex above
  // its centre. Faces counter-clockwise seen from outside.
  const double r = 0.6;
  std::ostringstream obj;
  if (!material_file.empty()) obj << "mtllib " << material_file << "\n";
  for (int i = 0; i < 3; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 3.0;
    obj << "v " << r * std::cos(a) << " 0 " << -r * std::sin(a) << "\n";
  }
  obj << "v 0 " << kTetrahedronHeight << " 0\n";
  if (!material_file.empty()) obj << "usemtl red\n";
  obj << "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
  return obj.str();
}

std::string red_mtl() {
  return "newmtl red\nKd 0.8 0.1 0.1\nKs 0.5 0.5 0.5\nNs 50\n";
}

std::string cube_off() {
  return R"(OFF
8 6 12
-1 -1 -1
 1 -1 -1
 1  1 -1
-1  1 -1
-1 -1  1
 1 -1  1
 1  1  1
-1  1  1
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3
)";
}

std::string write_grid_ply(const std::string& name, int n) {
  const int vertices = (n + 1) * (n + 1);
  const int faces = 2 * n * n;
  std::ostringstream header;
  header << "ply\nformat binary_little_endian 1.0\nelement vertex " << vertices
         << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
         << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string data = header.str();
  const std::size_t start = data.size();
  data.resize(start + static_cast<std::size_t>(vertices) * 12 +
              static_cast<std::size_t>(faces) * 13);
  char* p = data.data() + start;
  auto put = [&p](const auto& value) {
    std::memcpy(p, &value, sizeof value);
    p += sizeof value;
  };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      put(static_cast<float>(i) / n);
      put(0.0f);
      put(static_cast<float>(j) / n);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      // Counter-clockwise seen from +y.
      for (const auto& tri : {std::array<std::int32_t, 3>{a, c, b}, {b, c, d}}) {
        put(static_cast<std::uint8_t>(3));
        for (std::int32_t v : tri) put(v);
      }
    }
  }
  return write_model_file(name, data);
}

}  // namespace penumbra::testing
