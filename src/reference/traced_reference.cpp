#include "reference/traced_reference.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <optional>

#include "io/progress_bar.hpp"
#include "penumbra/error.hpp"
#include "reference/reference_cache.hpp"

namespace penumbra {

TracedReference traced_reference(Renderer& renderer, const RenderSettings& render,
                                 const ShadowSettings& shadow, int samples,
                                 const std::string& cache_dir) {
  RenderSettings view = render;
  view.view = View::Shadow;
  ShadowSettings no_shadow = shadow;
  no_shadow.technique = Technique::None;
  no_shadow.soft = false;            // only the moment techniques can be soft
  renderer.render(view, no_shadow);  // the G-buffer, and the fitted light views
  const SurfacePoints surfaces = renderer.read_surfaces();
  const int light_index = render.light_index;
  TracedReference r;
  r.light = make_reference_light(renderer.scene().lights[static_cast<std::size_t>(light_index)],
                                 renderer.light_view(light_index), shadow);
  r.rays = r.light.size > 0.0f ? samples : 1;
  const std::uint64_t key =
      reference_key(renderer.mesh(), surfaces, r.light, r.rays,
                    CasterCutouts(renderer.mesh(), renderer.scene().materials).hash());
  const auto start = std::chrono::steady_clock::now();
  std::optional<Image> cached;
  if (!cache_dir.empty()) {
    cached = load_cached_reference(cache_dir, key, surfaces.width, surfaces.height);
  }
  if (cached) {
    r.image = std::move(*cached);
    r.cached = true;
  } else {
    const ShadowRayTracer tracer(renderer.mesh(), renderer.scene().materials);
    ProgressBar progress("tracing the reference");
    TraceStats stats;
    const auto trace_start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    r.image = tracer.trace(
        surfaces, r.light, r.rays,
        [&](std::int64_t done, std::int64_t total) { progress.update(done, total); }, &stats);
    r.trace_cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    r.trace_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - trace_start).count();
    r.rays_traced = stats.rays;
    progress.finish();
    if (!cache_dir.empty()) {
      try {
        store_cached_reference(cache_dir, key, r.image);
      } catch (const RuntimeError& e) {
        std::fprintf(stderr, "penumbra: warning: reference not cached: %s\n", e.what());
      }
    }
  }
  // Counted from the surfaces, so a cached reference reports it too.
  r.unjudged_pixels = untraceable_points(surfaces, mesh_extent(renderer.mesh()));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (std::size_t i = 3; i < r.image.rgba.size(); i += 4) r.pixels += r.image.rgba[i] >= 0.5f;
  return r;
}

}  // namespace penumbra
