// The direct OBJ and binary PLY readers: any bytes are read to a mesh
// whose indices are all in range, left to assimp (nullopt), or refused
// with one RuntimeError; never a crash, a hang, or an allocation the
// file's size does not bound.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "penumbra/error.hpp"
#include "scene/direct_readers.hpp"

namespace {

void check(const std::optional<penumbra::DirectMesh>& mesh) {
  if (!mesh) return;
  for (const std::uint32_t i : mesh->mesh.indices) {
    if (i >= mesh->mesh.vertices.size()) std::abort();
  }
  if (mesh->mesh.indices.size() % 3 != 0) std::abort();
}

// The readers take a path: the input is written to one file per reader.
std::string write_input(const char* extension, const std::uint8_t* data, std::size_t size) {
  const std::string path = "/tmp/penumbra-fuzz-" + std::to_string(getpid()) + extension;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) std::abort();
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string obj = write_input(".obj", data, size);
  try {
    check(penumbra::read_obj_directly(obj));
  } catch (const penumbra::RuntimeError&) {
  }
  const std::string ply = write_input(".ply", data, size);
  try {
    check(penumbra::read_ply_directly(ply));
  } catch (const penumbra::RuntimeError&) {
  }
  std::remove(obj.c_str());
  std::remove(ply.c_str());
  return 0;
}
