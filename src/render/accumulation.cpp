#include "render/accumulation.hpp"

#include <cmath>
#include <vector>

#include "reference/light_sampling.hpp"
#include "shadow/light_view.hpp"

namespace penumbra {

SourceSample source_sample(const Light& light, const ShadowSettings& shadow, int k, int n,
                           int pattern) {
  SourceSample s;
  s.light = light;
  const glm::vec2 u = cmj_sample(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n),
                                 static_cast<std::uint32_t>(pattern));
  const glm::vec3 direction = glm::normalize(light.direction);
  // The shadow map's axes (as glm::lookAt builds them), so the square
  // lines up with the traced reference's.
  const glm::vec3 axis_u = glm::normalize(glm::cross(direction, stable_up(direction)));
  const glm::vec3 axis_v = glm::cross(axis_u, direction);
  switch (light.type) {
    case LightType::Spot: {
      const glm::vec2 offset = (u - 0.5f) * shadow.light_size;
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
      s.light.position += 0.5f * shadow.light_size * s.normal;
      break;
    }
    case LightType::Directional: {
      const float half_angle = 0.5f * glm::radians(shadow.sun_angle);
      const float sine = std::sin(0.5f * half_angle);
      const glm::vec3 c = uniform_cone(u, 2.0f * sine * sine);
      s.light.direction = -glm::normalize(c.x * axis_u + c.y * axis_v - c.z * direction);
      break;
    }
  }
  return s;
}

float source_weight(const Light& original, const SourceSample& sample, const glm::vec3& p,
                    const glm::vec3& n) {
  if (original.type == LightType::Directional) {
    return std::max(0.0f, glm::dot(n, -glm::normalize(sample.light.direction)));
  }
  const glm::vec3 to_light = sample.light.position - p;
  const float d2 = glm::dot(to_light, to_light);
  if (!(d2 > 0.0f)) return 0.0f;
  const glm::vec3 w = to_light / std::sqrt(d2);
  const float cos_receiver = glm::dot(n, w);
  const float cos_source = -glm::dot(sample.normal, w);
  if (cos_receiver <= 0.0f || cos_source <= 0.0f) return 0.0f;
  return cos_source * cos_receiver / d2;
}

Image render_accumulated(Renderer& renderer, const RenderSettings& render,
                         const ShadowSettings& shadow, const SsaoSettings& ssao) {
  const int n = shadow.accumulate;
  if (n <= 1 || is_map_view(render.view)) {
    renderer.render(render, shadow, ssao);
    return renderer.read_view();
  }
  const std::vector<Light> original = renderer.scene().lights;
  const auto shown = static_cast<std::size_t>(render.light_index);
  const bool weighted = render.view == View::Shadow && shown < original.size();
  Image sum(render.width, render.height);
  std::vector<double> numerator, denominator;
  SurfacePoints surfaces;
  for (int k = 0; k < n; ++k) {
    std::vector<Light> lights = original;
    std::vector<SourceSample> samples;
    for (std::size_t l = 0; l < lights.size(); ++l) {
      samples.push_back(source_sample(original[l], shadow, k, n, 0));
      lights[l] = samples.back().light;
    }
    renderer.set_lights(lights);
    ShadowSettings subframe = shadow;
    subframe.subframe = k;
    // Every light takes the same pattern, so the shaders' one point is
    // each spot light's.
    const glm::vec2 u =
        cmj_sample(static_cast<std::uint32_t>(k), static_cast<std::uint32_t>(n), 0u);
    subframe.subframe_u = u.x;
    subframe.subframe_v = u.y;
    renderer.render(render, subframe, ssao);
    const Image image = renderer.read_view();
    if (!weighted) {
      for (std::size_t i = 0; i < sum.rgba.size(); ++i) sum.rgba[i] += image.rgba[i] / n;
      continue;
    }
    if (k == 0) {
      surfaces = renderer.read_surfaces();  // the camera holds still
      numerator.assign(surfaces.size(), 0.0);
      denominator.assign(surfaces.size(), 0.0);
      sum = image;  // alpha: which pixels the shadow view judges
    }
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      if (!surfaces.covered[i]) continue;
      const float w =
          source_weight(original[shown], samples[shown], surfaces.position[i], surfaces.normal[i]);
      numerator[i] += double(w) * image.rgba[4 * i];
      denominator[i] += w;
    }
  }
  renderer.set_lights(original);
  if (weighted) {
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      if (!surfaces.covered[i]) continue;
      const float v = denominator[i] > 0.0 ? float(numerator[i] / denominator[i]) : 0.0f;
      sum.rgba[4 * i] = sum.rgba[4 * i + 1] = sum.rgba[4 * i + 2] = v;
    }
  }
  return sum;
}

}  // namespace penumbra
