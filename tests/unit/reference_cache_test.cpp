// Traced references on disk: stored and found again under the same key,
// missed under any other key or size, and a damaged entry is a miss.
#include "reference/reference_cache.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::path(PENUMBRA_TEST_OUTPUT) / "cache" / name;
  fs::remove_all(dir);
  return dir;
}

Image sample_reference(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float* p = image.pixel(x, y);
      p[0] = p[1] = p[2] = static_cast<float>(x * h + y) / static_cast<float>(w * h);
      p[3] = (x + y) % 3 == 0 ? 0.0f : 1.0f;
    }
  }
  return image;
}

TEST(ReferenceCache, StoresAndFindsAReference) {
  const fs::path dir = fresh_dir("roundtrip");
  const Image reference = sample_reference(7, 5);
  EXPECT_FALSE(load_cached_reference(dir.string(), 42, 7, 5));
  store_cached_reference(dir.string(), 42, reference);
  const std::optional<Image> found = load_cached_reference(dir.string(), 42, 7, 5);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->rgba, reference.rgba);
  EXPECT_FALSE(load_cached_reference(dir.string(), 43, 7, 5));
  EXPECT_FALSE(load_cached_reference(dir.string(), 42, 5, 7));
  // No temporary file left beside it.
  int files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos);
  }
  EXPECT_EQ(files, 1);
}

TEST(ReferenceCache, DamagedEntryIsAMiss) {
  const fs::path dir = fresh_dir("damaged");
  store_cached_reference(dir.string(), 7, sample_reference(4, 4));
  const fs::path file = cached_reference_path(dir.string(), 7);
  fs::resize_file(file, fs::file_size(file) - 3);
  EXPECT_FALSE(load_cached_reference(dir.string(), 7, 4, 4));
  std::ofstream(file, std::ios::binary) << "not a reference";
  EXPECT_FALSE(load_cached_reference(dir.string(), 7, 4, 4));
}

// Data damaged at the same size (zeroed, NaN, out of range) is caught by
// the checksum, and a value outside [0, 1] even with a matching checksum.
TEST(ReferenceCache, ChecksumCatchesDamageOfTheSameSize) {
  const fs::path dir = fresh_dir("checksum");
  store_cached_reference(dir.string(), 9, sample_reference(4, 4));
  const std::string file = cached_reference_path(dir.string(), 9);
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::string problem;
  ASSERT_TRUE(parse_cached_reference(bytes, 9, 4, 4, problem)) << problem;
  constexpr std::size_t kHeader = 40;
  std::string zeroed = bytes;
  std::fill(zeroed.begin() + kHeader, zeroed.end(), '\0');
  EXPECT_FALSE(parse_cached_reference(zeroed, 9, 4, 4, problem));
  EXPECT_EQ(problem, "its checksum does not match its data");
  std::string huge = bytes;
  const float big = 1e30f;
  std::memcpy(huge.data() + kHeader, &big, sizeof big);
  EXPECT_FALSE(parse_cached_reference(huge, 9, 4, 4, problem));
  const std::uint64_t sum = cache_checksum(std::string_view(huge).substr(kHeader));
  std::memcpy(huge.data() + 32, &sum, sizeof sum);
  EXPECT_FALSE(parse_cached_reference(huge, 9, 4, 4, problem));
  EXPECT_EQ(problem, "it holds a value that is not a visibility");
  std::ofstream(file, std::ios::binary) << zeroed;
  EXPECT_FALSE(load_cached_reference(dir.string(), 9, 4, 4));
}

// The key follows everything that decides the reference: the light, its
// size, the samples (only for an area light), the surfaces and the scene.
TEST(ReferenceCache, KeyFollowsEveryInput) {
  const Scene scene = *builtin_scene("spot");
  const TriangleMesh mesh = build_scene_mesh(scene);
  SurfacePoints surfaces(3, 2);
  for (std::size_t i = 0; i < surfaces.size(); ++i) {
    surfaces.position[i] = glm::vec3(static_cast<float>(i), 0.0f, 1.0f);
    surfaces.normal[i] = glm::vec3(0.0f, 1.0f, 0.0f);
    surfaces.covered[i] = i != 4;
  }
  ReferenceLight light;
  const std::uint64_t key = reference_key(mesh, surfaces, light, 256);
  EXPECT_EQ(key, reference_key(mesh, surfaces, light, 256));
  EXPECT_EQ(key, reference_key(mesh, surfaces, light, 64)) << "a point light takes one ray";
  ReferenceLight moved = light;
  moved.position.x += 1e-3f;
  EXPECT_NE(key, reference_key(mesh, surfaces, moved, 256));
  ReferenceLight area = light;
  area.size = 0.5f;
  const std::uint64_t area_key = reference_key(mesh, surfaces, area, 256);
  EXPECT_NE(key, area_key);
  EXPECT_NE(area_key, reference_key(mesh, surfaces, area, 64));
  SurfacePoints nudged = surfaces;
  nudged.normal[2].x = 1e-4f;
  EXPECT_NE(key, reference_key(mesh, nudged, light, 256));
  SurfacePoints uncovered = surfaces;
  uncovered.position[4] = glm::vec3(9.0f);  // unspecified where not covered
  EXPECT_EQ(key, reference_key(mesh, uncovered, light, 256));
  TriangleMesh other = mesh;
  other.vertices[0].position.y += 1e-3f;
  EXPECT_NE(key, reference_key(other, surfaces, light, 256));
  TriangleMesh bent = mesh;  // the rays' smooth surface follows the vertex normals
  bent.vertices[0].normal = glm::normalize(bent.vertices[0].normal + glm::vec3(0.1f, 0.0f, 0.0f));
  EXPECT_NE(key, reference_key(bent, surfaces, light, 256));
}

}  // namespace
}  // namespace penumbra
