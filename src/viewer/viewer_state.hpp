#pragma once
// What the viewer shows: the shared settings structs, the camera and the
// lights. The panel, the keys and the mouse change it only through the
// functions below, and a frame is rendered from it by frame_input() and
// render_frame(), so a test drives the viewer exactly as a person does,
// without a window.
#include <string>
#include <string_view>
#include <vector>

#include "penumbra/gl/gpu_profiler.hpp"
#include "penumbra/settings.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct ViewerState {
  std::string scene_argument;  // --scene as given, for "Copy as command"
  std::string model_argument;  // --model as given, which replaces --scene
  int camera_index = -1;       // --camera-index as given (-1: not given)
  bool ground = false;         // --ground as given
  std::string light_choice;    // --light as given (empty: not given), for the same
  Scene loaded;                // the scene as loaded, before any change
  RenderSettings render;       // width and height follow the window
  ShadowSettings shadow;
  SsaoSettings ssao;
  Camera camera;
  std::vector<Light> lights;
};

// The state at start: `loaded` with the camera and lights of `start` (the
// same scene after the command line's changes).
ViewerState make_viewer_state(std::string scene_argument, Scene loaded, const Scene& start,
                              const RenderSettings& render, const ShadowSettings& shadow,
                              const SsaoSettings& ssao = {});

// Render parameters the window decides (the image size), which the panel
// does not offer.
bool is_window_owned(const NumericParam<RenderSettings, int>& param);

// Sets a numeric parameter of the tables in penumbra/settings.hpp by its flag
// name, clamped to its range (light-index also to the scene's lights).
// Returns false for an unknown or window-owned name.
bool set_number(ViewerState& state, std::string_view name, double value);
bool set_flag(ViewerState& state, std::string_view name, bool value);
// "technique", "filter", "view", "ssao" or "ssao-half-resolution", by a
// name of its table. Returns false
// for an unknown parameter or value.
bool set_choice(ViewerState& state, std::string_view name, std::string_view value);
// The next (step > 0) or previous technique or view, wrapping around.
void step_technique(ViewerState& state, int step);
void step_view(ViewerState& state, int step);

// Replaces light `index`: the direction is normalized (a zero one keeps
// the old), the colour and intensity kept non-negative, the cone in range.
void set_light(ViewerState& state, int index, const Light& light);
void set_camera(ViewerState& state, const Camera& camera);

// One frame's input to the renderer, with combinations the renderer
// refuses made valid and each change explained in `notes` (the panel keeps
// what the person chose, so switching back restores it).
struct FrameInput {
  RenderSettings render;
  ShadowSettings shadow;
  SsaoSettings ssao;
  Camera camera;
  std::vector<Light> lights;
  std::vector<std::string> notes;
};

FrameInput frame_input(const ViewerState& state, int width, int height, int max_texture_size,
                       int max_shadow_samples = kMaxShadowMsaa);

// Renders the frame (throws as Renderer::render does).
void render_frame(Renderer& renderer, const FrameInput& frame, gl::GpuProfiler* profiler);

// The scene as shown: the loaded one with the frame's camera and lights.
Scene shown_scene(const ViewerState& state, const FrameInput& frame);

// The `penumbra render` arguments (after the program name) that re-make
// the frame headless into `output`.
std::vector<std::string> render_command_for(const ViewerState& state, const FrameInput& frame,
                                            const std::string& output);

// A file name that says what the frame shows, e.g.
// "penumbra-default-msm-sat-w8-soft-final.png".
std::string screenshot_name(const ViewerState& state, const FrameInput& frame);

}  // namespace penumbra
