#include "viewer/viewer_state.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "app/command_line.hpp"

namespace penumbra {

namespace {

template <class Owner, class Settings, class T, std::size_t N>
bool set_in_table(Owner& settings, const std::array<NumericParam<Settings, T>, N>& params,
                  std::string_view name, double value, T upper_limit) {
  for (const auto& p : params) {
    if (p.name != name) continue;
    const double max = std::min(static_cast<double>(p.max), static_cast<double>(upper_limit));
    double v = std::clamp(value, static_cast<double>(p.min), max);
    if constexpr (std::is_integral_v<T>) v = std::round(v);
    settings.*(p.field) = static_cast<T>(v);
    return true;
  }
  return false;
}

template <class E, std::size_t N>
bool set_from_table(E& field, const std::array<std::pair<E, std::string_view>, N>& table,
                    std::string_view value) {
  if (auto parsed = parse_enum<E>(EnumTable<E>(table), value)) {
    field = *parsed;
    return true;
  }
  return false;
}

template <class E, std::size_t N>
void step_in_table(E& field, const std::array<std::pair<E, std::string_view>, N>& table, int step) {
  std::size_t index = 0;
  while (index < N && table[index].first != field) ++index;
  const int n = static_cast<int>(N);
  const int next = ((static_cast<int>(index) + step) % n + n) % n;
  field = table[static_cast<std::size_t>(next)].first;
}

std::string name_of(View view) {
  return std::string(enum_name<View>(kViewNames, view));
}

}  // namespace

ViewerState make_viewer_state(std::string scene_argument, Scene loaded, const Scene& start,
                              const RenderSettings& render, const ShadowSettings& shadow,
                              const SsaoSettings& ssao) {
  ViewerState state;
  state.scene_argument = std::move(scene_argument);
  state.loaded = std::move(loaded);
  state.render = render;
  state.shadow = shadow;
  state.ssao = ssao;
  state.camera = start.camera;
  state.lights = start.lights;
  return state;
}

bool is_window_owned(const NumericParam<RenderSettings, int>& param) {
  return param.field == &RenderSettings::width || param.field == &RenderSettings::height;
}

bool set_number(ViewerState& state, std::string_view name, double value) {
  if (!std::isfinite(value)) return false;
  for (const auto& p : kRenderIntParams) {
    if (p.name == name && is_window_owned(p)) return false;
  }
  const int last_light = std::max(0, static_cast<int>(state.lights.size()) - 1);
  // Sample counts are powers of two: a slider's 3 or 6 goes to the nearest.
  if (name == "shadow-msaa") value = std::exp2(std::round(std::log2(std::max(value, 1.0))));
  if (name == "light-index") {
    return set_in_table(state.render, kRenderIntParams, name, value, last_light);
  }
  for (const SourceSizeParam& p : kSourceSizeParams) {
    if (p.name != name) continue;
    state.shadow.*(p.override_field) = static_cast<float>(
        std::clamp(value, static_cast<double>(p.min), static_cast<double>(p.max)));
    return true;
  }
  return set_in_table(state.shadow, kShadowFloatParams, name, value,
                      std::numeric_limits<float>::max()) ||
         set_in_table(state.ssao, kSsaoFloatParams, name, value,
                      std::numeric_limits<float>::max()) ||
         set_in_table(state.ssao, kSsaoIntParams, name, value, std::numeric_limits<int>::max()) ||
         set_in_table(state.shadow, kShadowIntParams, name, value,
                      std::numeric_limits<int>::max()) ||
         set_in_table(state.shadow, kAccumulateParams, name, value,
                      std::numeric_limits<int>::max()) ||
         set_in_table(state.shadow, kRendererShadowIntParams, name, value,
                      std::numeric_limits<int>::max()) ||
         set_in_table(state.shadow, kRendererShadowFloatParams, name, value,
                      std::numeric_limits<float>::max()) ||
         set_in_table(state.render, kRenderIntParams, name, value, std::numeric_limits<int>::max());
}

bool set_flag(ViewerState& state, std::string_view name, bool value) {
  for (const auto& p : kShadowFlagParams) {
    if (p.name == name) {
      state.shadow.*(p.field) = value;
      return true;
    }
  }
  return false;
}

bool set_choice(ViewerState& state, std::string_view name, std::string_view value) {
  if (name == "technique") return set_from_table(state.shadow.technique, kTechniqueNames, value);
  if (name == "filter") return set_from_table(state.shadow.filter, kFilterNames, value);
  if (name == "shadow-maps") {
    return set_from_table(state.shadow.shadow_maps, kShadowMapKindNames, value);
  }
  if (name == "view") return set_from_table(state.render.view, kViewNames, value);
  if (name == "ssao") return set_from_table(state.ssao.enabled, kOnOffNames, value);
  for (const auto& p : kShadowSwitchParams) {
    if (p.name == name) return set_from_table(state.shadow.*(p.field), kOnOffNames, value);
  }
  for (const auto& p : kRendererShadowSwitchParams) {
    if (p.name == name) return set_from_table(state.shadow.*(p.field), kOnOffNames, value);
  }
  if (name == "ssao-half-resolution") {
    return set_from_table(state.ssao.half_resolution, kOnOffNames, value);
  }
  return false;
}

void step_technique(ViewerState& state, int step) {
  step_in_table(state.shadow.technique, kTechniqueNames, step);
}

void step_view(ViewerState& state, int step) {
  step_in_table(state.render.view, kViewNames, step);
}

void set_light(ViewerState& state, int index, const Light& light) {
  if (index < 0 || index >= static_cast<int>(state.lights.size())) return;
  Light& target = state.lights[static_cast<std::size_t>(index)];
  const Light before = target;
  target = light;
  const float length = glm::length(light.direction);
  target.direction =
      length > 1e-6f && std::isfinite(length) ? light.direction / length : before.direction;
  target.color = glm::max(light.color, glm::vec3(0.0f));
  target.intensity = std::max(light.intensity, 0.0f);
  target.cone_degrees = std::clamp(light.cone_degrees, 0.1f, 89.9f);
}

void set_camera(ViewerState& state, const Camera& camera) {
  if (camera.position == camera.target) return;
  state.camera = camera;
}

FrameInput frame_input(const ViewerState& state, int width, int height, int max_texture_size,
                       int max_shadow_samples) {
  FrameInput f{state.render, state.shadow, state.ssao, state.camera, state.lights, {}};
  const int max_image = std::min(kMaxImageSize, max_texture_size);
  f.render.width = std::clamp(width, 1, max_image);
  f.render.height = std::clamp(height, 1, max_image);
  ShadowSettings& s = f.shadow;
  if (s.map_size > max_texture_size) {
    s.map_size = max_texture_size;
    f.notes.push_back("shadow-map size: this GPU's limit is " + std::to_string(max_texture_size));
  }
  if (s.shadow_msaa > max_shadow_samples) {
    s.shadow_msaa = max_shadow_samples;
    f.notes.push_back("shadow-msaa: this GPU's limit is " + std::to_string(max_shadow_samples));
  }
  if (s.soft && !supports_soft_shadows(s.technique, s.filter)) {
    s.soft = false;
    f.notes.push_back("soft: off (needs vsm, msm or msm16 with the sat filter)");
  }
  if (is_filterable(s.technique) && !supports_sat(s.technique) && s.filter == Filter::Sat &&
      s.blur > 0) {
    s.filter = Filter::Gaussian;
    f.notes.push_back("filter: gaussian (" +
                      std::string(enum_name<Technique>(kTechniqueNames, s.technique)) +
                      "'s exponentials exceed the summed-area table's range)");
  }
  RenderSettings& r = f.render;
  const int lights = static_cast<int>(f.lights.size());
  const bool light_view =
      r.view == View::Shadow || r.view == View::ShadowReference || is_map_view(r.view);
  if (lights == 0 && light_view) {
    f.notes.push_back(name_of(r.view) + ": the scene has no light; showing final");
    r.view = View::Final;
  }
  r.light_index = std::clamp(r.light_index, 0, std::max(0, lights - 1));
  if ((r.view == View::Moments || r.view == View::MomentsFiltered) && !is_filterable(s.technique)) {
    f.notes.push_back(name_of(r.view) + ": " +
                      std::string(enum_name<Technique>(kTechniqueNames, s.technique)) +
                      " stores depth, not moments; showing shadow-map");
    r.view = View::ShadowMap;
  }
  if (r.view == View::Ao && !f.ssao.enabled) {
    f.notes.push_back("ao: SSAO is off; showing final");
    r.view = View::Final;
  }
  if (s.shadow_maps == ShadowMapKind::Virtual && !supports_virtual_maps(s.technique)) {
    s.shadow_maps = ShadowMapKind::Cascades;
    f.notes.push_back(
        "shadow maps: cascades (virtual maps serve hard, pcf, pcss and backprojection)");
  }
  if (s.shadow_maps == ShadowMapKind::Virtual && is_map_view(r.view)) {
    f.notes.push_back(name_of(r.view) + ": virtual maps have no whole map; showing pages");
    r.view = View::Pages;
  }
  if (r.view == View::Pages && s.shadow_maps != ShadowMapKind::Virtual) {
    f.notes.push_back("pages: the maps are cascades; showing cascades");
    r.view = View::Cascades;
  }
  return f;
}

void render_frame(Renderer& renderer, const FrameInput& frame, gl::GpuProfiler* profiler) {
  renderer.set_camera(frame.camera);
  renderer.set_lights(frame.lights);
  renderer.render(frame.render, frame.shadow, frame.ssao, profiler);
}

Scene shown_scene(const ViewerState& state, const FrameInput& frame) {
  Scene scene = state.loaded;
  scene.camera = frame.camera;
  scene.lights = frame.lights;
  return scene;
}

std::vector<std::string> render_command_for(const ViewerState& state, const FrameInput& frame,
                                            const std::string& output) {
  const Scene edited = shown_scene(state, frame);
  return render_command_args({.scene_argument = state.scene_argument,
                              .model_argument = state.model_argument,
                              .light = state.light_choice,
                              .camera_index = state.camera_index,
                              .ground = state.ground,
                              .render = frame.render,
                              .shadow = frame.shadow,
                              .ssao = frame.ssao,
                              .original = &state.loaded,
                              .edited = &edited,
                              .output = output});
}

std::string screenshot_name(const ViewerState& state, const FrameInput& frame) {
  std::string scene = std::filesystem::path(state.model_argument.empty() ? state.scene_argument
                                                                         : state.model_argument)
                          .stem()
                          .string();
  if (scene.empty()) scene = "scene";
  const ShadowSettings& s = frame.shadow;
  // Appended piece by piece: GCC 12 misreports chains of operator+ on
  // temporaries (-Wrestrict).
  std::string name = "penumbra-";
  name += scene;
  name += '-';
  name += enum_name<Technique>(kTechniqueNames, s.technique);
  if (is_filterable(s.technique) && s.blur > 0) {
    name += '-';
    name += enum_name<Filter>(kFilterNames, s.filter);
    name += "-w";
    name += std::to_string(s.blur);
  }
  if (s.soft) name += "-soft";
  name += '-';
  name += name_of(frame.render.view);
  if (frame.render.view != View::Final && frame.render.view != View::Normals &&
      frame.render.view != View::Albedo) {
    name += "-light";
    name += std::to_string(frame.render.light_index);
  }
  name += ".png";
  return name;
}

}  // namespace penumbra
