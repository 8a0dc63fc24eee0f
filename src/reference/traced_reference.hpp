#pragma once
// The traced reference of a camera view: the G-buffer's surfaces, shadow
// rays to the light through Embree, cached on disk.
#include <cstdint>
#include <string>

#include "io/image.hpp"
#include "penumbra/settings.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "render/renderer.hpp"

namespace penumbra {

struct TracedReference {
  Image image;  // alpha 1 on the pixels compared
  ReferenceLight light;
  int rays = 1;
  bool cached = false;
  double seconds = 0.0;  // finding or tracing it, all told
  long pixels = 0;
  // Pixels that see geometry whose surface point could not be traced (not
  // finite, or absurd: traceable_point); they are not judged (alpha 0).
  std::int64_t unjudged_pixels = 0;
  // The tracing itself (0 when cached): shadow rays traced, and the
  // seconds they took on the clock and of CPU time (all threads).
  std::int64_t rays_traced = 0;
  double trace_seconds = 0.0;
  double trace_cpu_seconds = 0.0;
};

// The traced shadow of the surfaces the camera sees for render.light_index,
// from the cache when it holds them (`cache_dir` empty: no cache); `samples`
// rays per pixel for an area light. Shows a progress bar on a terminal.
TracedReference traced_reference(Renderer& renderer, const RenderSettings& render,
                                 const ShadowSettings& shadow, int samples,
                                 const std::string& cache_dir);

}  // namespace penumbra
