#include "render/accumulation.hpp"

#include <cmath>
#include <vector>

#include "core/light_sampling.hpp"
#include "penumbra/shadow/light_view.hpp"
#include "render/accumulator.hpp"

namespace penumbra {

SourceSample source_sample(const Light& light, const ShadowSettings& shadow, int k, int n,
                           int pattern) {
  SourceSample s;
  s.light = with_source_size(light, shadow);
  const glm::vec2 u =
      stratified_sample(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n),
                        static_cast<std::uint32_t>(pattern))
          .point;
  const glm::vec3 direction = glm::normalize(light.direction);
  // The shadow map's axes (as glm::lookAt builds them), so the square
  // lines up with the traced reference's.
  const glm::vec3 axis_u = glm::normalize(glm::cross(direction, stable_up(direction)));
  const glm::vec3 axis_v = glm::cross(axis_u, direction);
  switch (light.type) {
    case LightType::Spot: {
      const glm::vec2 offset = (u - 0.5f) * s.light.light_size;
      s.light.position += offset.x * axis_u + offset.y * axis_v;
      s.normal = direction;
      break;
    }
    case LightType::Point: {
      // Uniform over the sphere's surface; each receiver weighs the half
      // that faces it.
      const float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
      const float phi = 6.28318531f * u.y;
      s.normal = glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
      s.light.position += 0.5f * s.light.light_size * s.normal;
      break;
    }
    case LightType::Directional: {
      const float half_angle = 0.5f * glm::radians(s.light.sun_angle);
      const float sine = std::sin(0.5f * half_angle);
      const glm::vec3 c = uniform_cone(u, 2.0f * sine * sine);
      s.light.direction = -glm::normalize(c.x * axis_u + c.y * axis_v - c.z * direction);
      break;
    }
  }
  return s;
}

void render_subframe(Renderer& renderer, const std::vector<Light>& lights,
                     const RenderSettings& render, const ShadowSettings& shadow,
                     const SsaoSettings& ssao, int k, gl::GpuProfiler* profiler) {
  const int n = shadow.accumulate;
  std::vector<Light> moved = lights;
  ShadowSettings subframe = shadow;
  for (std::size_t l = 0; l < lights.size(); ++l) {
    const SourceSample sample = source_sample(lights[l], shadow, k, n, 0);
    moved[l] = sample.light;
    if (static_cast<int>(l) == render.light_index) {
      subframe.subframe_normal = {sample.normal.x, sample.normal.y, sample.normal.z};
    }
  }
  renderer.set_lights(moved);
  subframe.subframe = k;
  // Every light takes the same pattern, so the shaders' one point and
  // cell are each spot light's.
  const CellSample sample =
      stratified_sample(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n), 0u);
  const SquareCell& cell = sample.cell;
  subframe.subframe_u = sample.point.x;
  subframe.subframe_v = sample.point.y;
  subframe.subframe_cell = {cell.origin.x, cell.origin.y, cell.size.x, cell.size.y};
  subframe.subframe_cell_index = {static_cast<int>(cell.column), static_cast<int>(cell.columns),
                                  static_cast<int>(cell.row), static_cast<int>(cell.rows)};
  renderer.render(render, subframe, ssao, profiler);
}

bool weighs_subframes(const RenderSettings& render, const ShadowSettings& shadow) {
  return shadow.accumulate > 1 && render.view == View::Shadow;
}

Image render_accumulated(Renderer& renderer, const RenderSettings& render,
                         const ShadowSettings& shadow, const SsaoSettings& ssao) {
  if (shadow.accumulate <= 1 || is_map_view(render.view)) {
    renderer.render(render, shadow, ssao);
    return renderer.read_view();
  }
  const std::vector<Light> original = renderer.scene().lights;
  Accumulator accumulator;
  for (int k = 0; k < shadow.accumulate; ++k) {
    render_subframe(renderer, original, render, shadow, ssao, k);
    accumulator.add(renderer.view_source());
  }
  renderer.set_lights(original);
  return read_view_source(accumulator.result(weighs_subframes(render, shadow)));
}

}  // namespace penumbra
