// Scene files: any bytes are parsed to a scene or refused with an error
// (RuntimeError, UsageError), never a crash, a hang, or another exception.
#include <cstddef>
#include <cstdint>
#include <string>

#include "penumbra/error.hpp"
#include "scene/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // Models are looked up beside "fuzz/scene.json", a folder that does
    // not exist: a model object is refused after its keys are checked.
    penumbra::parse_scene_json(text, "fuzz/scene.json");
  } catch (const penumbra::RuntimeError&) {
  } catch (const penumbra::UsageError&) {
  }
  return 0;
}
