// Reads one model file as `penumbra render --model` does (load_model:
// the direct readers or assimp, normals, checks) and nothing else, so that
// benchmarks/load-models can time the reading apart from the rendering.
// Prints the counts and, with --hash, a hash of the triangles' corners, so
// that the two paths can be seen to give the very same triangles.
//
// Usage: load_model [--assimp] [--hash] FILE   (--assimp: the assimp path)
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>

#include "scene/model.hpp"

namespace {

// FNV-1a, 64 bits.
std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t h) {
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  return h;
}

}  // namespace

int main(int argc, char** argv) {
  bool assimp = false, hash = false;
  const char* path = nullptr;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--assimp") == 0) {
      assimp = true;
    } else if (std::strcmp(argv[i], "--hash") == 0) {
      hash = true;
    } else if (path == nullptr) {
      path = argv[i];
    } else {
      path = nullptr;
      break;
    }
  }
  if (path == nullptr) {
    std::fprintf(stderr, "usage: load_model [--assimp] [--hash] FILE\n");
    return 2;
  }
  try {
    const penumbra::Model model = penumbra::load_model(
        path, assimp ? penumbra::ModelReader::Assimp : penumbra::ModelReader::Any);
    const penumbra::TriangleMesh& mesh = model.mesh;
    std::printf("%zu triangles, %zu vertices", mesh.indices.size() / 3, mesh.vertices.size());
    if (hash) {
      // The triangles' corners, whatever the vertices' numbering: what a
      // renderer draws.
      std::uint64_t h = 14695981039346656037ull;
      for (const std::uint32_t i : mesh.indices) {
        h = hash_bytes(&mesh.vertices[i], sizeof(penumbra::Vertex), h);
      }
      std::printf(", mesh hash %016llx", static_cast<unsigned long long>(h));
    }
    std::printf("\n");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "load_model: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
