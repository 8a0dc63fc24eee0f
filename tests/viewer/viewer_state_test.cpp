// The viewer without a window: the edits the panel, the keys and the mouse
// make go through ViewerState, and each changes the rendered image.
#include "viewer/viewer_state.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "app/render_command.hpp"
#include "gpu_fixture.hpp"
#include "scene/builtin_scenes.hpp"
#include "viewer/light_drag.hpp"

namespace penumbra {
namespace {

using testing::GpuTest;

constexpr int kWidth = 128;
constexpr int kHeight = 96;

class ViewerStateTest : public GpuTest {
 protected:
  void SetUp() override {
    GpuTest::SetUp();  // the context, before any GL object
    scene_ = *builtin_scene("default");
    renderer_ = std::make_unique<Renderer>(scene_);
    RenderSettings render;
    ShadowSettings shadow;
    shadow.map_size = 256;
    state_ = make_viewer_state("default", scene_, scene_, render, shadow);
  }
  void TearDown() override {
    renderer_.reset();
    GpuTest::TearDown();
  }

  Image frame() {
    const FrameInput input = frame_input(state_, kWidth, kHeight, 16384);
    render_frame(*renderer_, input, nullptr);
    return renderer_->read_view();
  }

  Scene scene_;
  std::unique_ptr<Renderer> renderer_;
  ViewerState state_;
};

double mean_abs_difference(const Image& a, const Image& b) {
  EXPECT_EQ(a.rgba.size(), b.rgba.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < std::min(a.rgba.size(), b.rgba.size()); ++i) {
    sum += std::abs(a.rgba[i] - b.rgba[i]);
  }
  return sum / static_cast<double>(a.rgba.size());
}

double mean(const Image& image) {
  double sum = 0.0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) sum += image.rgba[i];
  return sum / static_cast<double>(image.rgba.size() / 4);
}

TEST_F(ViewerStateTest, EveryTechniqueAndViewRendersThroughTheKeys) {
  for (std::size_t t = 0; t < kTechniqueNames.size(); ++t) {
    for (std::size_t v = 0; v < kViewNames.size(); ++v) {
      SCOPED_TRACE(std::string(enum_name<Technique>(kTechniqueNames, state_.shadow.technique)) +
                   ", " + std::string(enum_name<View>(kViewNames, state_.render.view)));
      Image image;
      ASSERT_NO_THROW(image = frame());
      ASSERT_GT(image.width, 0);
      EXPECT_TRUE(std::all_of(image.rgba.begin(), image.rgba.end(),
                              [](float x) { return std::isfinite(x); }));
      EXPECT_GT(*std::max_element(image.rgba.begin(), image.rgba.end()), 0.0f);
      step_view(state_, 1);
    }
    EXPECT_EQ(state_.render.view, View::Final);  // wrapped around
    step_technique(state_, 1);
  }
  EXPECT_EQ(state_.shadow.technique, ShadowSettings{}.technique);
  step_technique(state_, -1);
  EXPECT_EQ(state_.shadow.technique, Technique::None);  // the one before hard
}

TEST_F(ViewerStateTest, PanelEditsChangeTheImage) {
  const Image hard = frame();
  ASSERT_TRUE(set_choice(state_, "technique", "none"));
  const Image unshadowed = frame();
  EXPECT_GT(mean(unshadowed), mean(hard) + 0.005);  // the shadows are gone

  ASSERT_TRUE(set_choice(state_, "technique", "vsm"));
  ASSERT_TRUE(set_choice(state_, "view", "moments-filtered"));
  const Image narrow = frame();
  ASSERT_TRUE(set_number(state_, "blur", 12));
  EXPECT_EQ(state_.shadow.blur, 12);
  EXPECT_GT(mean_abs_difference(frame(), narrow), 1e-4);

  ASSERT_TRUE(set_choice(state_, "technique", "msm"));
  ASSERT_TRUE(set_choice(state_, "filter", "sat"));
  ASSERT_TRUE(set_choice(state_, "view", "shadow"));
  // A penumbra wider than the fixed filter, so that soft shadows show.
  ASSERT_TRUE(set_number(state_, "light-size", 3.0));
  const Image fixed = frame();
  ASSERT_TRUE(set_flag(state_, "soft", true));
  const Image wide = frame();
  EXPECT_GT(mean_abs_difference(wide, fixed), 1e-4);
  ASSERT_TRUE(set_number(state_, "light-size", 0.05));
  EXPECT_GT(mean_abs_difference(frame(), wide), 1e-4);
}

TEST_F(ViewerStateTest, DraggingTheLightMovesItsShadow) {
  ASSERT_TRUE(set_choice(state_, "view", "shadow"));
  const Image before = frame();
  const Light& light = state_.lights[0];
  const LightDrag drag(light, renderer_->mesh().bounds().center());
  // Dragged a little at a time, as the mouse does: every step moves the
  // shadow, none jumps.
  Image previous = before;
  for (int step = 1; step <= 4; ++step) {
    set_light(state_, 0, drag.dragged(10.0f * step, 0.0f, glm::vec3(1.0f, 0.0f, 0.0f)));
    const Image now = frame();
    const double change = mean_abs_difference(now, previous);
    EXPECT_GT(change, 1e-4) << "step " << step;
    EXPECT_LT(change, 0.05) << "step " << step;
    previous = now;
  }
  EXPECT_NE(state_.lights[0].position, scene_.lights[0].position);
}

TEST_F(ViewerStateTest, RefusedCombinationsAreShownWithANote) {
  state_.shadow.soft = true;  // kept while a technique without it is shown
  ASSERT_TRUE(set_choice(state_, "technique", "pcf"));
  ASSERT_TRUE(set_choice(state_, "view", "moments"));
  FrameInput input = frame_input(state_, kWidth, kHeight, 16384);
  EXPECT_FALSE(input.shadow.soft);
  EXPECT_EQ(input.render.view, View::ShadowMap);
  EXPECT_EQ(input.notes.size(), 2u);
  EXPECT_TRUE(state_.shadow.soft);

  ASSERT_TRUE(set_choice(state_, "technique", "esm"));
  ASSERT_TRUE(set_choice(state_, "filter", "sat"));
  input = frame_input(state_, kWidth, kHeight, 1024);
  EXPECT_EQ(input.shadow.filter, Filter::Gaussian);
  EXPECT_EQ(input.render.view, View::Moments);
  ASSERT_TRUE(set_number(state_, "shadow-map-size", 4096));
  input = frame_input(state_, kWidth, kHeight, 1024);
  EXPECT_EQ(input.shadow.map_size, 1024);
  EXPECT_NO_THROW(render_frame(*renderer_, input, nullptr));
}

TEST_F(ViewerStateTest, NumbersAreClampedToTheirTables) {
  EXPECT_TRUE(set_number(state_, "esm-c", 1000.0));
  EXPECT_EQ(state_.shadow.esm_c, kEsmMaxC);
  EXPECT_TRUE(set_number(state_, "pcf-samples", 7.6));
  EXPECT_EQ(state_.shadow.pcf_samples, 8);
  EXPECT_TRUE(set_number(state_, "light-index", 3));
  EXPECT_EQ(state_.render.light_index, static_cast<int>(scene_.lights.size()) - 1);
  EXPECT_FALSE(set_number(state_, "width", 10));  // the window's
  EXPECT_FALSE(set_number(state_, "no-such-parameter", 1));
  EXPECT_FALSE(set_number(state_, "blur", std::nan("")));
  EXPECT_FALSE(set_choice(state_, "technique", "blurry"));
  // Sample counts snap to the nearest power of two, and to the GPU's limit.
  EXPECT_TRUE(set_number(state_, "shadow-msaa", 3));
  EXPECT_EQ(state_.shadow.shadow_msaa, 4);
  EXPECT_TRUE(set_number(state_, "shadow-msaa", 6));
  EXPECT_EQ(state_.shadow.shadow_msaa, 8);
  const FrameInput input = frame_input(state_, kWidth, kHeight, 16384, 4);
  EXPECT_EQ(input.shadow.shadow_msaa, 4);
  EXPECT_EQ(input.notes.size(), 1u);
}

// "Copy as command": the command, run headless, makes the same image.
TEST_F(ViewerStateTest, CopiedCommandRendersTheSameImage) {
  ASSERT_TRUE(set_choice(state_, "technique", "pcss"));
  ASSERT_TRUE(set_number(state_, "light-index", 1));
  ASSERT_TRUE(set_number(state_, "light-size", 0.8));
  Camera camera = state_.camera;
  camera.position += glm::vec3(1.5f, -0.5f, 0.25f);
  set_camera(state_, camera);
  Light spot = state_.lights[0];
  spot.position += glm::vec3(-1.0f, 0.5f, 0.0f);
  spot.color = {1.0f, 0.8f, 0.6f};
  set_light(state_, 0, spot);
  const Image shown = frame();

  const FrameInput input = frame_input(state_, kWidth, kHeight, 16384);
  const std::vector<std::string> args = render_command_for(state_, input, "copy.png");
  CLI::App app;
  RenderArgs parsed;
  add_render_command_options(*app.add_subcommand("render"), parsed);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  app.parse(reversed);
  parse_named_options(parsed.named, parsed.shadow, parsed.render);
  Scene scene = *builtin_scene(parsed.scene);
  apply_scene_options(parsed.scene_options, parsed.render.light_index, scene);
  Renderer headless(scene);
  headless.render(parsed.render, parsed.shadow);
  const Image again = headless.read_view();
  EXPECT_EQ(again.rgba, shown.rgba);
}

// A glTF scene viewed with --ground is copied with --ground.
TEST_F(ViewerStateTest, CopiedCommandKeepsTheGround) {
  const FrameInput input = frame_input(state_, kWidth, kHeight, 16384);
  const auto has_ground = [](const std::vector<std::string>& args) {
    return std::find(args.begin(), args.end(), "--ground") != args.end();
  };
  EXPECT_FALSE(has_ground(render_command_for(state_, input, "copy.png")));
  state_.ground = true;
  EXPECT_TRUE(has_ground(render_command_for(state_, input, "copy.png")));
}

TEST(ScreenshotName, SaysWhatIsShown) {
  ViewerState state;
  state.scene_argument = "scenes/room.json";
  FrameInput frame;
  frame.shadow.technique = Technique::Msm;
  frame.shadow.filter = Filter::Sat;
  frame.shadow.blur = 8;
  frame.shadow.soft = true;
  frame.render.view = View::Shadow;
  frame.render.light_index = 1;
  EXPECT_EQ(screenshot_name(state, frame), "penumbra-room-msm-sat-w8-soft-shadow-light1.png");
  frame.shadow = {};
  frame.render.view = View::Final;
  EXPECT_EQ(screenshot_name(state, frame), "penumbra-room-hard-final.png");
}

}  // namespace
}  // namespace penumbra
