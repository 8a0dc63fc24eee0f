// CPU-side hot paths (Google Benchmark): the moment-math references, scene
// building and upload preparation, light-view fitting, the Poisson set.
// GPU passes are measured by `penumbra bench`.
#include <benchmark/benchmark.h>

#include <random>

#include "penumbra/shadow/light_view.hpp"
#include "penumbra/shadow/moment_math.hpp"
#include "penumbra/shadow/poisson_disc.hpp"
#include "reference/shadow_ray_tracer.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/mesh.hpp"

namespace penumbra {
namespace {

void BM_HamburgerReference(benchmark::State& state) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<glm::dvec4> moments;
  for (int i = 0; i < 1024; ++i) {
    const double a = u(rng), b = u(rng), w = u(rng);
    auto m = [&](int k) { return w * std::pow(a, k) + (1 - w) * std::pow(b, k); };
    moments.push_back({m(1), m(2), m(3), m(4)});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        msm_hamburger_reference(moments[i++ % moments.size()], 0.6, 3e-5, kMsmBias32));
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HamburgerReference);

void BM_BuildDefaultSceneMesh(benchmark::State& state) {
  const Scene scene = *builtin_scene("default");
  for (auto _ : state) benchmark::DoNotOptimize(build_scene_mesh(scene));
}
BENCHMARK(BM_BuildDefaultSceneMesh);

void BM_FitSpotLight(benchmark::State& state) {
  const Scene scene = *builtin_scene("default");
  const TriangleMesh mesh = build_scene_mesh(scene);
  for (auto _ : state) benchmark::DoNotOptimize(fit_light_view(scene.lights[0], mesh, 2048));
  state.SetItemsProcessed(state.iterations() * static_cast<long>(mesh.indices.size() / 3));
}
BENCHMARK(BM_FitSpotLight);

void BM_PoissonSamples(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(poisson_square_samples());
}
BENCHMARK(BM_PoissonSamples);

// Shadow rays per CPU-second of the reference tracer (all its threads
// together, so the figure does not depend on how many cores are free):
// the default scene's ground seen from above as a 256 x 256 grid of
// points, towards the spot light's square source (range(0) rays per
// point).
void BM_ReferenceTracerRays(benchmark::State& state) {
  const Scene scene = *builtin_scene("default");
  const TriangleMesh mesh = build_scene_mesh(scene);
  const ShadowRayTracer tracer(mesh);
  SurfacePoints surfaces(256, 256);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * 256 + x;
      surfaces.position[i] = {-6.0f + 12.0f * x / 255.0f, 0.0f, -6.0f + 12.0f * y / 255.0f};
      surfaces.normal[i] = {0.0f, 1.0f, 0.0f};
      surfaces.covered[i] = 1;
    }
  }
  ShadowSettings settings;
  const ReferenceLight light =
      make_reference_light(scene.lights[0], fit_light_view(scene.lights[0], mesh, 2048), settings);
  const int rays = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(tracer.trace(surfaces, light, rays));
  state.SetItemsProcessed(state.iterations() * 256 * 256 * rays);
}
BENCHMARK(BM_ReferenceTracerRays)
    ->Arg(1)
    ->Arg(16)
    ->Arg(256)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace
}  // namespace penumbra

BENCHMARK_MAIN();
