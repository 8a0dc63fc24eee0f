#pragma once
// The viewer's Dear ImGui panel: the parameters of the shared settings
// tables that apply to what is shown (panel_relevance.hpp), the selected
// light, the camera, the display mode, live GPU times and the `penumbra
// render` command of what is shown; the settings scroll, the times and
// the command stay in view. Its edits go through
// the ViewerState functions, never into the renderer.
#include <optional>
#include <string>
#include <vector>

#include "penumbra/gl/gpu_profiler.hpp"
#include "viewer/viewer_state.hpp"

namespace penumbra {

struct PanelStatus {
  const FrameInput* frame = nullptr;     // the last frame rendered
  std::optional<gl::GpuFrameTimes> gpu;  // the latest finished frame's times
  double frame_ms = 0.0;                 // wall clock per frame, smoothed
  std::string renderer;                  // the GPU's name
  std::string command;                   // "penumbra render ..." of the frame
  std::string message;                   // the last screenshot, copy or error
  int max_texture_size = 16384;
  // --accumulate: sub-frames summed so far, of `accumulate` (0: not accumulating)
  int accumulated = 0;
  int accumulate = 0;
};

struct PanelActions {
  bool screenshot = false;
  bool copy_command = false;
  bool reset = false;
  // The parameters offered this frame (flag names; only those that apply
  // to the technique, filter and lights), and where the status part (GPU
  // times, command) ended, in screen units: what tests check.
  std::vector<std::string> parameters;
  float status_bottom = 0.0f;
  // The GPU time rows as drawn ("shadow depth   4.123 ms"), the frame's
  // total last; empty until the first times arrive.
  std::vector<std::string> timing_rows;
};

// Draws the panel at the window's right edge, `width` screen units wide,
// and applies its edits to `state`.
PanelActions draw_panel(ViewerState& state, const PanelStatus& status, float width);

// Writes the frame's notes (settings it had to change) over the 3D view's
// top-left corner, where they are seen whether or not the panel is.
void draw_notes(const FrameInput& frame);

}  // namespace penumbra
