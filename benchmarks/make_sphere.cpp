// Writes a sphere of about N triangles as OBJ (positions and faces, as a
// scan comes) or binary little-endian PLY, for benchmarks/load-models.
// A cube's six faces, each an n x n grid of quads split in two, pushed
// out to the unit sphere: 12 n^2 triangles, half a vertex per triangle,
// no pole where hundreds of triangles meet.
//
// Usage: make_sphere TRIANGLES obj|ply OUTPUT
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Point {
  float x, y, z;
};

// The cube's faces: a point of face f at grid coordinates (s, t) in [-1, 1].
Point cube_point(int face, float s, float t) {
  switch (face) {
    case 0:
      return {1.0f, t, -s};
    case 1:
      return {-1.0f, t, s};
    case 2:
      return {s, 1.0f, -t};
    case 3:
      return {s, -1.0f, t};
    case 4:
      return {s, t, 1.0f};
    default:
      return {-s, t, -1.0f};
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || (std::strcmp(argv[2], "obj") != 0 && std::strcmp(argv[2], "ply") != 0)) {
    std::fprintf(stderr, "usage: make_sphere TRIANGLES obj|ply OUTPUT\n");
    return 2;
  }
  const double wanted = std::atof(argv[1]);
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(wanted / 12.0))));
  const bool obj = std::strcmp(argv[2], "obj") == 0;
  std::FILE* out = std::fopen(argv[3], "wb");
  if (out == nullptr) {
    std::perror(argv[3]);
    return 1;
  }
  std::vector<Point> points;
  points.reserve(6 * static_cast<std::size_t>(n + 1) * (n + 1));
  for (int f = 0; f < 6; ++f) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const Point p = cube_point(f, -1.0f + 2.0f * i / n, -1.0f + 2.0f * j / n);
        const float length = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
        points.push_back({p.x / length, p.y / length, p.z / length});
      }
    }
  }
  std::vector<std::uint32_t> faces;
  faces.reserve(36 * static_cast<std::size_t>(n) * n);
  for (int f = 0; f < 6; ++f) {
    const std::uint32_t base = static_cast<std::uint32_t>(f * (n + 1) * (n + 1));
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::uint32_t a = base + j * (n + 1) + i, b = a + 1, c = a + (n + 1), d = c + 1;
        faces.insert(faces.end(), {a, b, d, a, d, c});
      }
    }
  }
  const std::size_t triangles = faces.size() / 3;
  if (obj) {
    for (const Point& p : points) std::fprintf(out, "v %.6f %.6f %.6f\n", p.x, p.y, p.z);
    for (std::size_t t = 0; t < triangles; ++t) {
      std::fprintf(out, "f %u %u %u\n", faces[3 * t] + 1, faces[3 * t + 1] + 1,
                   faces[3 * t + 2] + 1);
    }
  } else {
    std::fprintf(out,
                 "ply\nformat binary_little_endian 1.0\nelement vertex %zu\n"
                 "property float x\nproperty float y\nproperty float z\nelement face %zu\n"
                 "property list uchar int vertex_indices\nend_header\n",
                 points.size(), triangles);
    std::fwrite(points.data(), sizeof(Point), points.size(), out);
    for (std::size_t t = 0; t < triangles; ++t) {
      const unsigned char three = 3;
      std::fwrite(&three, 1, 1, out);
      std::fwrite(&faces[3 * t], sizeof(std::uint32_t), 3, out);
    }
  }
  if (std::fclose(out) != 0) {
    std::perror(argv[3]);
    return 1;
  }
  std::printf("%zu triangles, %zu vertices\n", triangles, points.size());
  return 0;
}
