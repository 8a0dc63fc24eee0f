#include "viewer/panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>

#include "app/scene_options.hpp"
#include "render/pass_timing.hpp"
#include "viewer/key_bindings.hpp"
#include "viewer/panel_relevance.hpp"

namespace penumbra {

namespace {

constexpr const char* kSoftwareTimingNote =
    "software renderer: these times are of the CPU emulating the GPU (compute passes run "
    "outside the timer queries), not GPU times";

// The longest pass name, the width of the time rows' name column.
constexpr int kPassNameWidth = [] {
  std::size_t width = 0;
  for (const std::string_view name : gl::kGpuPassNames) width = std::max(width, name.size());
  return static_cast<int>(width);
}();

void tooltip(std::string_view text) {
  if (!text.empty() && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

// Parameters whose default is small against their range get a logarithmic
// slider, so the default's neighbourhood is not a few pixels wide.
template <class Settings, class T>
bool logarithmic(const NumericParam<Settings, T>& p) {
  const T start = Settings{}.*(p.field);
  if constexpr (std::is_integral_v<T>) {
    return p.max / std::max<T>(p.min, 1) > 256;
  } else {
    return start < (p.max - p.min) / 50;
  }
}

// Whether the panel offers a parameter this frame (and notes that it did).
using Offer = std::function<bool(std::string_view)>;

template <class Owner, class Settings, std::size_t N>
void float_sliders(ViewerState& state, const Owner& settings,
                   const std::array<NumericParam<Settings, float>, N>& params, const Offer& offer) {
  for (const auto& p : params) {
    if (!offer(p.name)) continue;
    float value = settings.*(p.field);
    const std::string label(p.name);
    ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoRoundToFormat;
    if (logarithmic(p)) flags |= ImGuiSliderFlags_Logarithmic;
    if (ImGui::SliderFloat(label.c_str(), &value, p.min, p.max, "%.6g", flags)) {
      set_number(state, p.name, value);
    }
    tooltip(p.help);
  }
}

template <class Owner, class Settings, std::size_t N>
void int_sliders(ViewerState& state, const Owner& settings,
                 const std::array<NumericParam<Settings, int>, N>& params, int limit,
                 bool skip_window_owned, const Offer& offer) {
  for (const auto& p : params) {
    if constexpr (std::is_same_v<Settings, RenderSettings>) {
      if (skip_window_owned && is_window_owned(p)) continue;
    }
    if (!offer(p.name)) continue;
    int value = settings.*(p.field);
    const int max = std::min(p.max, limit);
    const std::string label(p.name);
    ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
    if (logarithmic(p)) flags |= ImGuiSliderFlags_Logarithmic;
    if (ImGui::SliderInt(label.c_str(), &value, p.min, max, "%d", flags)) {
      set_number(state, p.name, value);
    }
    tooltip(p.help);
  }
}

template <class E, std::size_t N>
void choice_combo(ViewerState& state, const char* name, E current,
                  const std::array<std::pair<E, std::string_view>, N>& table,
                  std::string_view help) {
  const std::string shown(enum_name<E>(EnumTable<E>(table), current));
  if (ImGui::BeginCombo(name, shown.c_str())) {
    for (const auto& [value, text] : table) {
      const std::string item(text);
      if (ImGui::Selectable(item.c_str(), value == current)) set_choice(state, name, text);
    }
    ImGui::EndCombo();
  }
  tooltip(help);
}

void light_section(ViewerState& state) {
  if (state.lights.empty()) {
    ImGui::TextDisabled("the scene has no light");
    return;
  }
  const int index =
      std::clamp(state.render.light_index, 0, static_cast<int>(state.lights.size()) - 1);
  Light light = state.lights[static_cast<std::size_t>(index)];
  ImGui::Text("light %d: %s", index,
              std::string(enum_name<LightType>(kLightTypeNames, light.type)).c_str());
  bool changed = false;
  for (const auto& p : kLightVectorParams) {
    if (!applies_to(p.scope, light.type)) continue;
    const std::string label(p.name);
    glm::vec3& v = light.*(p.field);
    if (p.field == &Light::color) {
      changed |= ImGui::ColorEdit3(label.c_str(), &v.x, ImGuiColorEditFlags_Float);
    } else {
      changed |= ImGui::DragFloat3(label.c_str(), &v.x, 0.01f, 0.0f, 0.0f, "%.3f");
    }
    tooltip(p.help);
  }
  for (const auto& p : kLightScalarParams) {
    if (!applies_to(p.scope, light.type)) continue;
    const std::string label(p.name);
    changed |= ImGui::SliderFloat(label.c_str(), &(light.*(p.field)), p.min,
                                  p.field == &Light::intensity ? 1000.0f : p.max, "%.4g",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_NoRoundToFormat);
    tooltip(p.help);
  }
  if (changed) set_light(state, index, light);
}

void camera_section(ViewerState& state) {
  Camera camera = state.camera;
  bool changed = false;
  for (const auto& p : kCameraVectorParams) {
    const std::string label(p.name);
    changed |= ImGui::DragFloat3(label.c_str(), &(camera.*(p.field)).x, 0.01f, 0.0f, 0.0f, "%.3f");
    tooltip(p.help);
  }
  for (const auto& p : kCameraScalarParams) {
    const std::string label(p.name);
    changed |= ImGui::SliderFloat(label.c_str(), &(camera.*(p.field)), p.min, p.max, "%.1f");
    tooltip(p.help);
  }
  if (changed) set_camera(state, camera);
}

void timing_section(const PanelStatus& status, std::vector<std::string>& rows) {
  ImGui::Text("frame %.1f ms (%.1f fps while changing)", status.frame_ms,
              status.frame_ms > 0.0 ? 1000.0 / status.frame_ms : 0.0);
  if (is_software_renderer(status.renderer)) {
    // llvmpipe runs compute dispatches outside its timer queries: its pass
    // times are neither GPU times nor comparable with each other.
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", kSoftwareTimingNote);
    ImGui::PopTextWrapPos();
  }
  if (status.accumulate > 0) {
    ImGui::Text("accumulated %d / %d sub-frames%s", status.accumulated, status.accumulate,
                status.accumulated < status.accumulate ? " (hold still)" : "");
  }
  if (!status.gpu) {
    ImGui::TextDisabled("GPU times: waiting for the first results");
    return;
  }
  // One line of text per pass, name and milliseconds padded to columns in
  // the panel's monospaced font: no table column can clip a name or a
  // time to its first letters.
  auto row = [&](std::string_view name, double ms) {
    char text[64];
    std::snprintf(text, sizeof text, "%-*.*s %9.3f ms", kPassNameWidth,
                  static_cast<int>(name.size()), name.data(), ms);
    ImGui::TextUnformatted(text);
    rows.emplace_back(text);
  };
  for (std::size_t p = 0; p < status.gpu->pass_ms.size(); ++p) {
    if (status.gpu->ran[p]) row(gl::kGpuPassNames[p], status.gpu->pass_ms[p]);
  }
  row("GPU frame", status.gpu->total_ms);
}

void help_section() {
  for (const KeyBinding& b : kKeyBindings) {
    if (b.what.empty()) continue;
    const std::string keys(b.keys), what(b.what);
    ImGui::BulletText("%s: %s", keys.c_str(), what.c_str());
  }
  ImGui::BulletText("left drag: orbit; right or middle drag: pan; wheel: zoom");
  ImGui::BulletText("shift or ctrl + left drag: move the selected light");
}

// The height the status part of the panel needs: the frame time, the
// software-renderer note, a row per pass timed, the buttons, the command
// wrapped to the panel's width and the last message.
float status_section_height(const PanelStatus& status) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float wrap = ImGui::GetContentRegionAvail().x;
  auto text_height = [&](const std::string& text) {
    return ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap).y + style.ItemSpacing.y;
  };
  float height = style.ItemSpacing.y * 2.0f + line;  // separator, frame time
  if (is_software_renderer(status.renderer)) height += text_height(kSoftwareTimingNote);
  if (status.gpu) {
    const auto rows = std::count(status.gpu->ran.begin(), status.gpu->ran.end(), true) + 1;
    height += static_cast<float>(rows) * line;
  } else {
    height += line;
  }
  height += ImGui::GetFrameHeightWithSpacing();  // the buttons
  height += text_height(status.command);
  if (!status.message.empty()) height += text_height(status.message);
  return height + style.WindowPadding.y;
}

}  // namespace

PanelActions draw_panel(ViewerState& state, const PanelStatus& status, float width) {
  PanelActions actions;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - width, viewport->WorkPos.y));
  ImGui::SetNextWindowSize(ImVec2(width, viewport->WorkSize.y));
  ImGui::Begin("penumbra", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                   ImGuiWindowFlags_NoScrollWithMouse);
  ImGui::PushItemWidth(-ImGui::GetFontSize() * 11.5f);

  const FrameInput* frame = status.frame;
  ImGui::TextDisabled("%s", status.renderer.c_str());
  if (frame != nullptr) {
    const std::string& scene =
        state.model_argument.empty() ? state.scene_argument : state.model_argument;
    ImGui::Text("%s, %d x %d", scene.c_str(), frame->render.width, frame->render.height);
  }

  // The settings scroll; the times and the command below them stay in
  // view (up to 60 % of the panel's height; beyond it they scroll too).
  const float status_height =
      std::min(status_section_height(status), 0.6f * ImGui::GetContentRegionAvail().y);
  ImGui::BeginChild("settings", ImVec2(0.0f, -status_height));
  const Offer offer = [&](std::string_view name) {
    if (!parameter_applies(name, state.shadow, state.ssao, state.lights)) return false;
    actions.parameters.emplace_back(name);
    return true;
  };
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (offer("view")) {
      choice_combo(state, "view", state.render.view, kViewNames,
                   "what the window shows: the final image, a light's shadow factor, its map, "
                   "the moments before and after the filter, normals or albedo");
    }
    int_sliders(state, state.render, kRenderIntParams,
                std::max(1, static_cast<int>(state.lights.size())) - 1, true, offer);
  }
  if (ImGui::CollapsingHeader("Shadows", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (offer("technique")) {
      choice_combo(state, "technique", state.shadow.technique, kTechniqueNames,
                   "the shadow technique");
    }
    if (offer("filter")) {
      choice_combo(state, "filter", state.shadow.filter, kFilterNames,
                   "filter of the vsm/esm/msm/msm16/evsm2/evsm4 maps: separable Gaussian or "
                   "summed-area table");
    }
    if (offer("shadow-maps")) {
      choice_combo(state, "shadow-maps", state.shadow.shadow_maps, kShadowMapKindNames,
                   "directional and spot lights: cascades and spot maps, or virtual shadow maps "
                   "(hard, pcf)");
    }
    for (const auto& p : kShadowFlagParams) {
      if (!offer(p.name)) continue;
      bool value = state.shadow.*(p.field);
      const std::string label(p.name);
      if (ImGui::Checkbox(label.c_str(), &value)) set_flag(state, p.name, value);
      tooltip(p.help);
    }
    const auto switches = [&](const auto& table) {
      for (const auto& p : table) {
        if (!offer(p.name)) continue;
        choice_combo(state, std::string(p.name).c_str(), state.shadow.*(p.field), kOnOffNames,
                     p.help);
      }
    };
    switches(kShadowSwitchParams);
    switches(kRendererShadowSwitchParams);
    int_sliders(state, state.shadow, kShadowIntParams, status.max_texture_size, false, offer);
    int_sliders(state, state.shadow, kAccumulateParams, std::numeric_limits<int>::max(), false,
                offer);
    float_sliders(state, state.shadow, kShadowFloatParams, offer);
    int_sliders(state, state.shadow, kRendererShadowIntParams, std::numeric_limits<int>::max(),
                false, offer);
    float_sliders(state, state.shadow, kRendererShadowFloatParams, offer);
    // Every light of the kind at once, as --light-size and --sun-angle.
    for (const SourceSizeParam& p : kSourceSizeParams) {
      if (!offer(p.name)) continue;
      float value = state.shadow.*(p.override_field);
      const std::string label(p.name);
      if (ImGui::SliderFloat(label.c_str(), &value, p.min, p.max, "%.6g",
                             ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoRoundToFormat)) {
        set_number(state, p.name, value);
      }
      tooltip(p.help);
    }
  }
  if (ImGui::CollapsingHeader("Ambient occlusion")) {
    for (const auto& p : kSsaoSwitchParams) {
      if (!offer(p.name)) continue;
      choice_combo(state, std::string(p.name).c_str(), state.ssao.*(p.field), kOnOffNames, p.help);
    }
    int_sliders(state, state.ssao, kSsaoIntParams, std::numeric_limits<int>::max(), false, offer);
    float_sliders(state, state.ssao, kSsaoFloatParams, offer);
  }
  if (ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen)) light_section(state);
  if (ImGui::CollapsingHeader("Camera")) camera_section(state);
  if (ImGui::CollapsingHeader("Keys and mouse")) help_section();
  ImGui::EndChild();

  ImGui::BeginChild("status");
  ImGui::Separator();
  timing_section(status, actions.timing_rows);
  actions.copy_command = ImGui::Button("Copy as command");
  ImGui::SameLine();
  actions.screenshot = ImGui::Button("Screenshot");
  ImGui::SameLine();
  actions.reset = ImGui::Button("Reset");
  tooltip("camera and lights back to where they started");
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%s", status.command.c_str());
  if (!status.message.empty()) ImGui::TextUnformatted(status.message.c_str());
  ImGui::PopTextWrapPos();
  actions.status_bottom = ImGui::GetItemRectMax().y;
  ImGui::EndChild();
  ImGui::PopItemWidth();
  ImGui::End();
  return actions;
}

void draw_notes(const FrameInput& frame) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  ImVec2 at(8.0f, 6.0f);
  for (const std::string& note : frame.notes) {
    draw->AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), IM_COL32(0, 0, 0, 220), note.c_str());
    draw->AddText(at, IM_COL32(255, 205, 80, 255), note.c_str());
    at.y += line;
  }
}

}  // namespace penumbra
