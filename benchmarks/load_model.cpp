// Reads one model file as `penumbra render --model` does (load_model:
// the direct readers or assimp, normals, checks) and nothing else, so that
// benchmarks/load-models can time the reading apart from the rendering.
//
// Usage: load_model FILE [assimp]   ("assimp": the assimp path, for comparison)
#include <cstdio>
#include <cstring>
#include <exception>

#include "scene/model.hpp"

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: load_model FILE [assimp]\n");
    return 2;
  }
  const bool assimp = argc == 3 && std::strcmp(argv[2], "assimp") == 0;
  try {
    const penumbra::Model model = penumbra::load_model(
        argv[1], assimp ? penumbra::ModelReader::Assimp : penumbra::ModelReader::Any);
    std::printf("%zu triangles, %zu vertices\n", model.mesh.indices.size() / 3,
                model.mesh.vertices.size());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "load_model: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
