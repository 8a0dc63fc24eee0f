// Writes penumbra::shadow_lookup_glsl() with the default bindings to the
// file named by its argument: the lookup include installed as
// share/penumbra/penumbra_shadows.glsl (run at build time; needs no GPU).
// A declaration the prefixing cannot read fails the build here.
#include <cstdio>
#include <fstream>
#include <iostream>

#include "penumbra/shadow_maps.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: " << argv[0] << " OUTPUT.glsl\n";
    return 2;
  }
  try {
    const std::string text = penumbra::shadow_lookup_glsl();
    const std::string temporary = std::string(argv[1]) + ".tmp";
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out || std::rename(temporary.c_str(), argv[1]) != 0) {
      std::cerr << "penumbra: error: cannot write " << argv[1] << "\n";
      std::remove(temporary.c_str());
      return 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "penumbra: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
