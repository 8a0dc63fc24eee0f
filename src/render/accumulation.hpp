#pragma once
// Accumulated soft shadows: the frame rendered N times, each sub-frame
// with every light moved to another point of its source and its shadow
// maps rendered from there, shaded with the chosen technique (hard or
// pcf), and averaged on the GPU (render/accumulator.hpp). As N grows the
// average converges to the area light's shadow, as the traced reference
// computes it: the shadow view weights sub-frame k's shadow at each pixel
// by what that point of the source sends the pixel (cos theta_source
// cos theta_receiver / d^2 for a spot light's square or a point light's
// sphere, cos theta_receiver for the sun's disc of directions; the
// lighting shader's accumulate_source_weight), so it estimates the same
// ratio of irradiances; the other camera views are plain means.
//
// The points are stratified, one in each of N cells of equal area that
// partition the source's square for any N (square_cell in
// core/light_sampling.hpp), multi-jittered (Kensler 2013) with one fixed
// pattern, so every run gives the same image; a spot light's hard test
// dithers each pixel's rays over the sub-frame's cell, so the N sub-frames
// cover the whole source once.
#include <glm/glm.hpp>

#include <vector>

#include "io/image.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/settings.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// A light moved to point k (0 <= k < n) of its source, and the source's
// outward normal there (spot: its direction; point: the sphere's normal;
// directional: unused, zero).
struct SourceSample {
  Light light;
  glm::vec3 normal{0.0f};
};
SourceSample source_sample(const Light& light, const ShadowSettings& shadow, int k, int n,
                           int pattern);

// Renders sub-frame k of shadow.accumulate: every light of `lights` (the
// scene's own, unmoved) moved to point k of its source. Leaves the
// renderer's lights moved; the caller restores them.
void render_subframe(Renderer& renderer, const std::vector<Light>& lights,
                     const RenderSettings& render, const ShadowSettings& shadow,
                     const SsaoSettings& ssao, int k, gl::GpuProfiler* profiler = nullptr);

// Whether `render` shows the shadow view that sub-frames write with their
// source weights (the Accumulator's weighted result).
bool weighs_subframes(const RenderSettings& render, const ShadowSettings& shadow);

// The view render.view after shadow.accumulate sub-frames (one plain
// render and read_view() when it is 1, or for a map view). Leaves the
// renderer's lights as they were.
Image render_accumulated(Renderer& renderer, const RenderSettings& render,
                         const ShadowSettings& shadow, const SsaoSettings& ssao = {});

}  // namespace penumbra
