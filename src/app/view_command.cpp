#include "app/view_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "app/command_line.hpp"
#include "app/help_formatter.hpp"
#include "app/light_choice.hpp"
#include "app/option_style.hpp"
#include "app/scene_source.hpp"
#include "io/image.hpp"
#include "penumbra/error.hpp"
#include "penumbra/gl/gpu_profiler.hpp"
#include "render/accumulation.hpp"
#include "render/accumulator.hpp"
#include "render/present_pass.hpp"
#include "render/renderer.hpp"
#include "scene/scene_file.hpp"
#include "viewer/imgui_layer.hpp"
#include "viewer/key_bindings.hpp"
#include "viewer/mouse_controls.hpp"
#include "viewer/orbit_camera.hpp"
#include "viewer/panel.hpp"
#include "viewer/viewer_state.hpp"
#include "viewer/window.hpp"

namespace penumbra {

namespace {

// The panel's width in screen units.
constexpr float kPanelWidth = 400.0f;

PngEncoding png_encoding(View view) {
  return view == View::Final ? PngEncoding::Srgb : PngEncoding::Linear;
}

// `name` in the current folder, or name-2, name-3, ... if it exists.
std::string unused_path(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path base(name);
  fs::path path = base;
  for (int n = 2; fs::exists(path); ++n) {
    path = base.stem().string() + "-" + std::to_string(n) + base.extension().string();
  }
  return path.string();
}

// The window's back buffer, as an image (rows top to bottom).
Image read_window(glm::ivec2 size) {
  std::vector<unsigned char> bytes(static_cast<std::size_t>(size.x) * size.y * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  Image image(size.x, size.y);
  for (int y = 0; y < size.y; ++y) {
    const unsigned char* row = bytes.data() + static_cast<std::size_t>(size.y - 1 - y) * size.x * 4;
    for (int x = 0; x < size.x; ++x) {
      float* p = image.pixel(x, y);
      for (int c = 0; c < 4; ++c) p[c] = row[x * 4 + c] / 255.0f;
    }
  }
  return image;
}

void check_gl_errors(const gl::DebugOutput& debug) {
  if (debug.error_count() > 0) {
    throw RuntimeError("OpenGL reported " + std::to_string(debug.error_count()) +
                       " error(s); last: " + debug.last_error());
  }
}

// What a key does; the actions that need the frame's image are left in
// `actions` for after it is rendered.
void apply_key(KeyAction action, ViewerState& state, PanelActions& actions, bool& panel_visible,
               Window& window) {
  switch (action) {
    case KeyAction::NextTechnique:
      step_technique(state, 1);
      break;
    case KeyAction::PreviousTechnique:
      step_technique(state, -1);
      break;
    case KeyAction::NextView:
      step_view(state, 1);
      break;
    case KeyAction::PreviousView:
      step_view(state, -1);
      break;
    case KeyAction::Screenshot:
      actions.screenshot = true;
      break;
    case KeyAction::CopyCommand:
      actions.copy_command = true;
      break;
    case KeyAction::Reset:
      actions.reset = true;
      break;
    case KeyAction::TogglePanel:
      panel_visible = !panel_visible;
      break;
    case KeyAction::Quit:
      window.close();
      break;
  }
}

}  // namespace

void add_view_command_options(CLI::App& command, ViewArgs& args) {
  add_scene_source_options(command, args.scene, args.model, args.camera_index, args.ground);
  add_light_choice_option(command, args.light);
  in_group(command.add_flag("--verbose", args.verbose,
                            "print the GPU in use and driver messages, and on closing the "
                            "frames drawn and the panel's last GPU times"),
           OptionGroup::Output);
  add_number(command, "frames", args.frames,
             "scripted mode: render this many frames ignoring mouse and keys, then close (0: run "
             "until the window is closed)",
             0, 1000000, OptionGroup::Output);
  in_group(command
               .add_option("--screenshot", args.screenshot,
                           "on closing, write the last frame's view as 'render' writes it (.png, "
                           ".exr)")
               ->type_name("FILE"),
           OptionGroup::Output);
  in_group(command
               .add_option("--capture-window", args.capture_window,
                           "on closing, write the whole window, panel included (.png)")
               ->type_name("FILE"),
           OptionGroup::Output);
  add_render_options(command, args.render, args.named);
  add_shadow_options(command, args.shadow, args.named);
  add_accumulate_option(command, args.shadow);
  add_ssao_options(command, args.ssao);
  add_scene_options(command, args.scene_options);
  command.footer(examples_footer({
      {"the default scene; the panel edits every setting", "penumbra view"},
      {"the bunny scene file, with moment soft shadows",
       "penumbra view --scene scenes/bunny.json --technique msm --filter sat --soft"},
  }));
}

int run_view_command(ViewArgs& args) {
  parse_named_options(args.named, args.shadow, args.render);
  validate(args.render);
  validate(args.shadow);
  if (!args.screenshot.empty()) {
    image_format_for(args.screenshot);
    check_output_path(args.screenshot);
  }
  if (!args.capture_window.empty()) {
    if (image_format_for(args.capture_window) != ImageFormat::Png) {
      throw UsageError("--capture-window '" + args.capture_window + "' must end in .png");
    }
    check_output_path(args.capture_window);
  }
  Scene loaded = resolve_scene_source(args.scene, args.model, args.camera_index, args.ground);
  apply_light_choice(args.light, loaded);
  check_light_index(args.render.light_index, loaded);
  Scene start = loaded;
  apply_scene_options(args.scene_options, args.render.light_index, start);

  const bool scripted = args.frames > 0;
  Window window({.width = args.render.width + static_cast<int>(kPanelWidth),
                 .height = args.render.height,
                 .title = "penumbra: " + (args.model.empty() ? args.scene : args.model),
                 .vsync = !scripted,
                 .verbose = args.verbose});
  if (epoxy_gl_version() < 45) {
    throw RuntimeError("the window's OpenGL context is version " +
                       std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))) +
                       ", 4.5 is required");
  }
  const std::string gpu_name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (args.verbose) std::fprintf(stderr, "penumbra: %s via GLFW\n", gpu_name.c_str());
  GLint max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  GLint max_shadow_samples = 1;
  glGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &max_shadow_samples);

  ImGuiLayer imgui(window);
  Renderer renderer(start);
  PresentPass present;
  // Read a few frames late, so the frame loop never waits for the GPU.
  gl::GpuProfiler profiler(4, /*serialize=*/false);

  ViewerState state =
      make_viewer_state(args.scene, std::move(loaded), start, args.render, args.shadow, args.ssao);
  state.model_argument = args.model;
  state.camera_index = args.camera_index;
  state.ground = args.ground;
  state.light_choice = args.light;
  OrbitCamera orbit(state.camera);
  MouseControls mouse(renderer.mesh().bounds().center());

  PanelStatus status;
  status.renderer = gpu_name;
  status.max_texture_size = max_texture;
  std::optional<FrameInput> shown;  // the last frame rendered
  bool have_image = false;          // the renderer's view holds `shown`
  // What `shown` was rendered from, as its `penumbra render` arguments: a
  // frame whose arguments are the same is the same image, not rendered
  // again.
  std::vector<std::string> shown_args;
  int drawn_frames = 0, rendered_frames = 0;
  std::vector<std::string> timing_rows;  // the panel's GPU times, as last drawn
  // Frames to draw before waiting for events again: Dear ImGui settles a
  // change (a hover, an opened list) over a few frames.
  int busy_frames = 3;
  ViewSource shown_source;  // its image: the renderer's view, or the accumulated one
  // With --accumulate N: the sub-frames summed for `shown` so far.
  Accumulator accumulator;
  bool panel_visible = true;
  glm::dvec2 last_cursor(0.0);

  for (int frame_index = 0; !window.should_close(); ++frame_index) {
    // Idle: nothing moved or changed in the last frames, so wait for an
    // event (or half a second, to show new GPU times) instead of drawing.
    if (scripted || busy_frames > 0) {
      window.poll();
    } else {
      window.wait(0.5);
    }
    // The frame time counts from here: the wait for an event is not work.
    const auto start_time = std::chrono::steady_clock::now();
    const int rendered_before = rendered_frames;
    busy_frames = std::max(0, busy_frames - 1);
    const MouseInput pointer = window.mouse();
    if (!window.keys().empty() || pointer.left || pointer.right || pointer.middle ||
        pointer.scroll != 0.0 || pointer.cursor != last_cursor) {
      busy_frames = 3;
    }
    last_cursor = pointer.cursor;
    const glm::ivec2 fb = window.framebuffer_size();
    const glm::ivec2 win = window.window_size();
    const float scale = win.x > 0 ? static_cast<float>(fb.x) / static_cast<float>(win.x) : 1.0f;
    const int panel_pixels =
        panel_visible ? std::min(fb.x, static_cast<int>(std::lround(kPanelWidth * scale))) : 0;
    const glm::ivec2 view(fb.x - panel_pixels, fb.y);

    PanelActions actions;
    if (!scripted) {
      for (const KeyPress& key : window.keys()) {
        if (imgui.wants_keyboard()) break;
        const std::optional<KeyAction> action = action_for_key(key.key, key.mods);
        if (!action) continue;
        apply_key(*action, state, actions, panel_visible, window);
      }
    }

    imgui.begin_frame();
    if (!scripted) {
      mouse.update(window.mouse(), panel_visible && imgui.wants_mouse(), view.y, state, orbit);
    }
    if (panel_visible) {
      status.frame = shown ? &*shown : nullptr;
      const PanelActions clicked = draw_panel(state, status, kPanelWidth);
      timing_rows = clicked.timing_rows;
      actions.screenshot |= clicked.screenshot;
      actions.copy_command |= clicked.copy_command;
      actions.reset |= clicked.reset;
    }
    if (actions.reset) {
      state.camera = start.camera;
      state.lights = start.lights;
    }

    // With --accumulate N the viewer adds one sub-frame per frame while the
    // frame's arguments hold still, shows the mean so far, and stops
    // rendering once it has all N; any change starts the sum again.
    if (view.x > 0 && view.y > 0) {
      FrameInput frame = frame_input(state, view.x, view.y, max_texture, max_shadow_samples);
      std::vector<std::string> args = render_command_for(state, frame, "");
      const bool changed = !have_image || args != shown_args;
      const bool accumulating = frame.shadow.accumulate > 1 && !is_map_view(frame.render.view);
      if (changed) accumulator.reset();
      const bool refine = accumulating && accumulator.count() < frame.shadow.accumulate;
      status.accumulate = accumulating ? frame.shadow.accumulate : 0;
      if (changed || refine) {
        busy_frames = 3;
        if (changed) have_image = false;
        profiler.begin_frame();
        try {
          if (accumulating) {
            renderer.set_camera(frame.camera);
            render_subframe(renderer, frame.lights, frame.render, frame.shadow, frame.ssao,
                            accumulator.count(), &profiler);
            accumulator.add(renderer.view_source());
            shown_source = accumulator.result(weighs_subframes(frame.render, frame.shadow));
          } else {
            render_frame(renderer, frame, &profiler);
            shown_source = renderer.view_source();
          }
          // An OpenGL error (out of memory for a huge view) ends the
          // viewer with one message, rather than a loop of failing frames.
          check_gl_errors(window.debug_output());
          have_image = true;
          ++rendered_frames;
        } catch (const UsageError& e) {
          if (scripted) throw;  // nobody is there to change the settings
          status.message = e.what();
          accumulator.reset();
        }
        profiler.end_frame();
        shown = std::move(frame);
        shown_args = std::move(args);
      }
      status.accumulated = accumulator.count();
    }
    while (std::optional<gl::GpuFrameTimes> times = profiler.read(false)) {
      status.gpu = times;
      busy_frames = 3;  // the times' table sizes its columns over a few frames
    }
    if (shown) {
      status.command =
          shell_command(render_command_for(state, *shown, screenshot_name(state, *shown)));
    }

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb.x, fb.y);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.12f, 0.12f, 0.13f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (have_image) present.execute(shown_source, 0, {0, 0, view.x, view.y});
    if (shown) draw_notes(*shown);
    imgui.end_frame();

    if (have_image && actions.screenshot) {
      const std::string path = unused_path(screenshot_name(state, *shown));
      try {
        write_image(read_view_source(shown_source), path, png_encoding(shown->render.view));
        status.message = "saved " + path;
      } catch (const RuntimeError& e) {
        status.message = e.what();
      }
    }
    if (actions.copy_command) {
      window.set_clipboard(status.command);
      status.message = "copied the command to the clipboard";
    }
    ++drawn_frames;
    const bool last = scripted && frame_index + 1 >= args.frames;
    if (last && !args.capture_window.empty()) {
      write_png(read_window(fb), args.capture_window, PngEncoding::Linear);
    }
    window.swap_buffers();

    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - start_time).count();
    if (rendered_frames > rendered_before) {
      status.frame_ms = status.frame_ms == 0.0 ? ms : 0.9 * status.frame_ms + 0.1 * ms;
    }
    if (last) window.close();
  }

  if (args.verbose) {
    std::fprintf(stderr, "penumbra: %d frames drawn, %d rendered\n", drawn_frames, rendered_frames);
    // The last frame's GPU times as the panel showed them.
    for (const std::string& row : timing_rows) std::fprintf(stderr, "penumbra: %s\n", row.c_str());
  }
  if (!args.screenshot.empty()) {
    if (!shown) throw RuntimeError("no frame was rendered for --screenshot");
    write_image(read_view_source(shown_source), args.screenshot, png_encoding(shown->render.view));
  }
  check_gl_errors(window.debug_output());
  return 0;
}

}  // namespace penumbra
