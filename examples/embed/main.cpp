// An engine of its own (headless EGL context, forward renderer, mesh)
// that shadows its scene with penumbra's shadow core: a spot light and a
// sun with cascades, the technique switched at run time.
//
//   embed --headless -o out.png [--technique pcf,vsm,msm] [--lights spot|sun|both]
//         [--filter gaussian|sat [--soft]] [--view final|shadow] [--width N] [--height N]
//         [--map-size N]
//
// Several techniques render one after another with the same ShadowMaps
// and the same shader (the block says which technique the maps hold), to
// out-<technique>.png each. --view shadow writes the first light's shadow
// factor (1 = lit) instead of the lit image.
#include <penumbra/penumbra.hpp>

#include <cstdio>
#include <exception>
#include <glm/gtc/matrix_transform.hpp>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "forward_renderer.hpp"
#include "headless_context.hpp"
#include "mesh.hpp"
#include "png_writer.hpp"
#include "scene.hpp"

namespace {

struct Options {
  bool headless = false;
  std::string output;
  std::vector<penumbra::Technique> techniques{penumbra::Technique::Pcf};
  penumbra::Filter filter = penumbra::ShadowMapSettings{}.filter;
  bool soft = false;  // moment soft shadows (vsm, msm, msm16 with --filter sat)
  bool spot = true, sun = true;
  bool shadow_view = false;
  int width = 640, height = 360, map_size = 1024;
};

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "embed: error: " << message << "\n";
  std::exit(2);
}

int parse_int(std::string_view flag, const std::string& value, int lo, int hi) {
  try {
    std::size_t used = 0;
    const int n = std::stoi(value, &used);
    if (used == value.size() && n >= lo && n <= hi) return n;
  } catch (const std::exception&) {
  }
  usage_error(std::string(flag) + " " + value + ": expected an integer in " + std::to_string(lo) +
              ".." + std::to_string(hi));
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--headless") {
      o.headless = true;
      continue;
    }
    if (flag == "--soft") {
      o.soft = true;
      continue;
    }
    if (i + 1 >= argc) usage_error(std::string(flag) + ": expected a value (or unknown flag)");
    const std::string value = argv[++i];
    if (flag == "-o" || flag == "--output") {
      o.output = value;
    } else if (flag == "--technique") {
      // The names of penumbra's own table: one name per technique everywhere.
      o.techniques.clear();
      for (std::size_t at = 0; at <= value.size();) {
        const std::size_t comma = std::min(value.find(',', at), value.size());
        const std::string name = value.substr(at, comma - at);
        const auto t = penumbra::parse_enum<penumbra::Technique>(penumbra::kTechniqueNames, name);
        if (!t) usage_error("--technique " + name + ": unknown technique");
        o.techniques.push_back(*t);
        at = comma + 1;
      }
    } else if (flag == "--filter") {
      // How vsm, esm, evsm and msm filter their maps.
      const auto f = penumbra::parse_enum<penumbra::Filter>(penumbra::kFilterNames, value);
      if (!f) usage_error("--filter " + value + ": unknown filter");
      o.filter = *f;
    } else if (flag == "--lights") {
      if (value != "spot" && value != "sun" && value != "both") {
        usage_error("--lights " + value + ": expected spot, sun or both");
      }
      o.spot = value != "sun";
      o.sun = value != "spot";
    } else if (flag == "--view") {
      if (value != "final" && value != "shadow")
        usage_error("--view " + value + ": expected final or shadow");
      o.shadow_view = value == "shadow";
    } else if (flag == "--width") {
      o.width = parse_int(flag, value, 1, 8192);
    } else if (flag == "--height") {
      o.height = parse_int(flag, value, 1, 8192);
    } else if (flag == "--map-size") {
      o.map_size = parse_int(flag, value, 16, 8192);
    } else {
      usage_error("unknown flag " + std::string(flag));
    }
  }
  if (!o.headless)
    usage_error("only --headless rendering is built in; give --headless -o FILE.png");
  if (o.output.empty()) usage_error("-o FILE.png is required");
  return o;
}

// out.png -> out-vsm.png
std::string output_for(const std::string& output, penumbra::Technique t) {
  const std::string name(penumbra::enum_name<penumbra::Technique>(penumbra::kTechniqueNames, t));
  const std::size_t dot = output.rfind('.');
  return dot == std::string::npos ? output + "-" + name
                                  : output.substr(0, dot) + "-" + name + output.substr(dot);
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  try {
    embed::HeadlessContext context;
    const embed::Mesh mesh = embed::make_scene_mesh();
    const embed::GpuMesh gpu_mesh(mesh);
    embed::ForwardRenderer renderer(options.width, options.height);

    // The engine's lights, and the same lights as penumbra sees them.
    std::vector<embed::EngineLight> lights;
    std::vector<penumbra::Light> shadow_lights;
    if (options.spot) {
      const glm::vec3 direction = glm::normalize(embed::kSpotTarget - embed::kSpotPosition);
      lights.push_back({.directional = false,
                        .position = embed::kSpotPosition,
                        .direction = direction,
                        .color = embed::kSpotColor,
                        .cone_degrees = embed::kSpotConeDegrees});
      shadow_lights.push_back({.type = penumbra::LightType::Spot,
                               .position = embed::kSpotPosition,
                               .direction = direction,
                               .cone_degrees = embed::kSpotConeDegrees});
    }
    if (options.sun) {
      const glm::vec3 direction = glm::normalize(embed::kSunDirection);
      lights.push_back({.directional = true, .direction = direction, .color = embed::kSunColor});
      shadow_lights.push_back({.type = penumbra::LightType::Directional, .direction = direction});
    }

    // The engine's camera, and the frustum the sun's cascades follow.
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::mat4 view = glm::lookAt(embed::kCameraPosition, embed::kCameraTarget, up);
    const glm::mat4 projection = glm::perspective(glm::radians(embed::kCameraFovDegrees), aspect,
                                                  embed::kCameraNear, embed::kCameraFar);
    const penumbra::CameraFrustum camera{
        .position = embed::kCameraPosition,
        .forward = glm::normalize(embed::kCameraTarget - embed::kCameraPosition),
        .up = up,
        .fov_y = glm::radians(embed::kCameraFovDegrees),
        .aspect = aspect,
        .near_plane = embed::kCameraNear,
        .far_plane = embed::kCameraFar};

    penumbra::ShadowMaps shadows;
    penumbra::ShadowMapSettings settings;
    settings.map_size = options.map_size;
    settings.filter = options.filter;
    settings.soft = options.soft;
    for (const penumbra::Technique technique : options.techniques) {
      settings.technique = technique;
      // Fit the views to the camera and the casters (the mesh's own
      // positions, read in place), draw the casters into each view, filter.
      shadows.update(shadow_lights, camera, {.positions = mesh.vertices, .indices = mesh.indices},
                     settings);
      shadows.render([&](const penumbra::CasterView&) { gpu_mesh.draw(); });
      // The engine's own pass, reading the shadows through penumbra_shadow().
      shadows.bind();
      renderer.draw(gpu_mesh, projection * view, lights, options.shadow_view ? 0 : -1);
      const std::string file =
          options.techniques.size() == 1 ? options.output : output_for(options.output, technique);
      embed::write_png(file, options.width, options.height, renderer.read_rgb());
      std::printf("%s: %s, %d shadow views\n", file.c_str(),
                  std::string(penumbra::enum_name<penumbra::Technique>(penumbra::kTechniqueNames,
                                                                       technique))
                      .c_str(),
                  shadows.view_count());
    }
  } catch (const penumbra::UsageError& e) {
    std::cerr << "embed: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "embed: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
