// What fitting costs when the camera moves, against the triangle count:
// the cascades of a directional light (ShadowMaps::update() and the
// renderer refit them on every camera move) and the camera's own near and
// far planes (the renderer's), through the caster bounds built once
// (caster_bounds.hpp), on a height field of about 4 thousand and of about
// 4 million triangles. Prints each median and their ratio; the claim is a
// ratio within 2. The clipping of every triangle that the bounds replace
// is timed too, for a few moves. With "tight", the cascades are fitted to
// the geometry their slices see (--tight-cascades).
//
// Usage: fit_scaling [MOVES] [tight]   (default 64 camera positions)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_transform.hpp>
#include <string_view>
#include <vector>

#include "penumbra/shadow/caster_bounds.hpp"
#include "penumbra/shadow/light_view.hpp"
#include "penumbra/shadow/shadow_views.hpp"

namespace {

using namespace penumbra;
using Clock = std::chrono::steady_clock;

struct HeightField {
  std::vector<glm::vec3> vertices;
  std::vector<std::uint32_t> indices;
};

// n x n quads over [-50, 50]^2, two triangles each, with hills of a few
// units (so that cascades' columns and the camera's frustum cut through
// sloped geometry, not a plane).
HeightField height_field(int n) {
  HeightField h;
  h.vertices.reserve(static_cast<std::size_t>(n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const float x = -50.0f + 100.0f * static_cast<float>(i) / n;
      const float z = -50.0f + 100.0f * static_cast<float>(j) / n;
      const float y =
          2.5f * std::sin(0.21f * x) * std::cos(0.17f * z) + 0.8f * std::sin(0.9f * x + 0.4f * z);
      h.vertices.emplace_back(x, y, z);
    }
  }
  h.indices.reserve(static_cast<std::size_t>(n) * n * 6);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::uint32_t>(j * (n + 1) + i);
      const auto c = a + static_cast<std::uint32_t>(n + 1);
      for (std::uint32_t k : {a, c, c + 1, a, c + 1, a + 1}) h.indices.push_back(k);
    }
  }
  return h;
}

// Camera position k of a walk across the field, looking ahead and down.
CameraFrustum camera_at(int k) {
  const float s = static_cast<float>(k) * 0.37f;
  CameraFrustum c;
  c.position =
      glm::vec3(-30.0f + 0.9f * static_cast<float>(k), 6.0f + std::sin(s), 10.0f * std::cos(s));
  c.forward = glm::normalize(glm::vec3(std::cos(0.5f * s), -0.35f, -std::sin(0.5f * s) - 0.4f));
  c.up = glm::vec3(0.0f, 1.0f, 0.0f);
  c.fov_y = glm::radians(50.0f);
  c.aspect = 16.0f / 9.0f;
  c.near_plane = 0.1f;
  c.far_plane = 80.0f;
  return c;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Timing {
  std::size_t triangles = 0;
  double build_ms = 0.0;     // the bounds, once
  double fit_ms = 0.0;       // median per move: cascades and camera planes
  double clip_all_ms = 0.0;  // median per move, clipping every triangle
  // The bounds' fits against the clipped ones (the moves timed both ways).
  int cascades_compared = 0, cascades_equal = 0;
  double worst_z0_steps = 0.0, worst_z1_steps = 0.0;  // outwards, in the cascade's depth steps
  double worst_near = 1.0, worst_far = 1.0;           // camera: bounded / exact
};

struct Fit {
  LightShadowViews cascades;
  float zmin = 1e30f, zmax = 0.0f;  // the camera's nearest and farthest depth
};

Timing measure(int n, int moves, int clip_moves, bool tight) {
  const HeightField field = height_field(n);
  Timing t;
  t.triangles = field.indices.size() / 3;
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.45f, -1.0f, 0.3f));
  ShadowSettings settings;
  settings.cascades = 4;
  settings.map_size = 2048;
  settings.tight_cascades = tight;
  const PositionSpan positions(field.vertices);

  CasterBoundsCache cache;
  auto fit = [&](int k, bool through_bounds) {
    const CameraFrustum camera = camera_at(k);
    const ShadowViewInputs inputs = shadow_view_inputs(sun, camera, settings);
    const glm::mat4 view =
        glm::lookAt(camera.position, camera.position + camera.forward, camera.up);
    const float ky = std::tan(0.5f * camera.fov_y);
    Fit f;
    if (through_bounds) {
      f.cascades = fit_shadow_views(inputs, positions, field.indices, cache);
      const CasterHierarchy& world = cache.bounds(positions, field.indices, glm::mat4(1.0f));
      frustum_depth_range(view, camera.aspect * ky, ky, positions, field.indices, world, f.zmin,
                          f.zmax);
    } else {
      f.cascades = fit_shadow_views(inputs, positions, field.indices);
      frustum_depth_range(view, camera.aspect * ky, ky, positions, field.indices, f.zmin, f.zmax);
    }
    return f;
  };

  Clock::time_point start = Clock::now();
  fit(0, true);  // builds the bounds, the light's and the world's
  t.build_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  std::vector<double> fits, clips;
  std::vector<Fit> bounded;
  for (int k = 1; k <= moves; ++k) {
    start = Clock::now();
    bounded.push_back(fit(k, true));
    fits.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  for (int k = 1; k <= std::min(clip_moves, moves); ++k) {
    start = Clock::now();
    const Fit exact = fit(k, false);
    clips.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    // How tight: each cascade's z0 and z1 against the clipped fit's, in
    // its steps (a 17th of z1 - z0: its near end snaps to them), and the
    // camera's nearest and farthest depth.
    const Fit& b = bounded[static_cast<std::size_t>(k - 1)];
    for (std::size_t c = 0; c < exact.cascades.views.size(); ++c) {
      const LightView &e = exact.cascades.views[c], &v = b.cascades.views[c];
      const double step = (double(e.z1) - e.z0) / 17.0;
      t.worst_z0_steps = std::max(t.worst_z0_steps, (double(e.z0) - v.z0) / step);
      t.worst_z1_steps = std::max(t.worst_z1_steps, (double(v.z1) - e.z1) / step);
      t.cascades_equal += e.z0 == v.z0 && e.z1 == v.z1;
      ++t.cascades_compared;
    }
    t.worst_near = std::min(t.worst_near, double(b.zmin) / exact.zmin);
    t.worst_far = std::max(t.worst_far, double(b.zmax) / exact.zmax);
  }
  t.fit_ms = median(fits);
  t.clip_all_ms = median(clips);
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const int moves = argc > 1 ? std::max(1, std::atoi(argv[1])) : 64;
  const bool tight = argc > 2 && std::string_view(argv[2]) == "tight";
  std::printf(
      "fit_scaling: 4 %scascades (map 2048) and the camera's planes, refitted at %d camera "
      "positions\n",
      tight ? "tight " : "", moves);
  // 2 n^2 triangles: 45 -> 4,050; 1415 -> 4,004,450.
  const Timing small = measure(45, moves, 16, tight);
  const Timing large = measure(1415, moves, 3, tight);
  for (const Timing& t : {small, large}) {
    std::printf(
        "%9zu triangles: bounds built once %8.1f ms; per move %7.3f ms (clipping every triangle: "
        "%8.2f ms)\n",
        t.triangles, t.build_ms, t.fit_ms, t.clip_all_ms);
    std::printf(
        "    against clipping: %d of %d cascades the same, z0 at most %.2f and z1 %.2f of their "
        "steps out; camera's nearest depth x%.3f, farthest x%.3f\n",
        t.cascades_equal, t.cascades_compared, t.worst_z0_steps, t.worst_z1_steps, t.worst_near,
        t.worst_far);
  }
  std::printf("ratio per move, %zu / %zu triangles: %.2fx (clipping every triangle: %.0fx)\n",
              large.triangles, small.triangles, large.fit_ms / small.fit_ms,
              large.clip_all_ms / small.clip_all_ms);
  return 0;
}
