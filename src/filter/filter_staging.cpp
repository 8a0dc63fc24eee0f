#include "penumbra/filter/filter_staging.hpp"

#include <epoxy/gl.h>

#include "penumbra/gl/context.hpp"

namespace penumbra {

bool stages_in_shared_memory(FilterStaging staging) {
  if (staging != FilterStaging::Automatic) return staging == FilterStaging::SharedMemory;
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer == nullptr || !gl::is_cpu_rasterizer(renderer);
}

}  // namespace penumbra
