#pragma once
// The viewer's Dear ImGui panel: every parameter of the shared settings
// tables, the selected light, the camera, the display mode, live GPU times
// and the `penumbra render` command of what is shown. Its edits go through
// the ViewerState functions, never into the renderer.
#include <optional>
#include <string>

#include "gl/gpu_profiler.hpp"
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
};

// Draws the panel at the window's right edge, `width` screen units wide,
// and applies its edits to `state`.
PanelActions draw_panel(ViewerState& state, const PanelStatus& status, float width);

// Writes the frame's notes (settings it had to change) over the 3D view's
// top-left corner, where they are seen whether or not the panel is.
void draw_notes(const FrameInput& frame);

}  // namespace penumbra
