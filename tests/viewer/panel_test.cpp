// The panel without a window: Dear ImGui laid out on a 1280 x 720 display
// with no renderer. It offers what applies to the technique, filter and
// lights, and its times and command stay on screen whatever it lists.
#include "viewer/panel.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>

#include "scene/builtin_scenes.hpp"
#include "viewer/panel_relevance.hpp"

namespace penumbra {
namespace {

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

class PanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(1280.0f, 720.0f);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // builds the font atlas
    const Scene scene = *builtin_scene("default");
    state_ = make_viewer_state("default", scene, scene, RenderSettings{}, ShadowSettings{});
    // What a software renderer's frame shows: every pass of the longest
    // frame the viewer runs timed (the two-pass Gaussian, then the mip
    // chain; the fused pass, the summed-area table's and the bench's copy
    // never run beside them), a long command, a message.
    status_.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    gl::GpuFrameTimes times;
    for (const gl::GpuPass pass :
         {gl::GpuPass::ShadowDepth, gl::GpuPass::Resolve, gl::GpuPass::FilterHorizontal,
          gl::GpuPass::FilterVertical, gl::GpuPass::Mips, gl::GpuPass::GBuffer,
          gl::GpuPass::AmbientOcclusion, gl::GpuPass::Lighting}) {
      times.ran[static_cast<std::size_t>(pass)] = true;
    }
    status_.gpu = times;
    status_.command =
        "penumbra render --technique=msm16 --filter=sat --blur=8 --shadow-map-size=4096 --soft "
        "--light-size=1.5 --camera-position=-6,5,6 --camera-target=0,0.5,0 "
        "--light-position=-3,8,2 --light-direction=0.3,-1,-0.2 --width=880 "
        "--output=penumbra-default-msm16-sat-w8-soft-final.png";
    status_.message = "copied the command to the clipboard";
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // Draws the panel as the viewer does (two frames: Dear ImGui sizes its
  // windows in the first) and returns the second frame's actions.
  PanelActions draw() {
    PanelActions actions;
    for (int frame = 0; frame < 2; ++frame) {
      ImGui::NewFrame();
      actions = draw_panel(state_, status_, 400.0f);
      ImGui::Render();
    }
    return actions;
  }

  ViewerState state_;
  PanelStatus status_;
};

TEST_F(PanelTest, OffersOnlyWhatAppliesToTheTechnique) {
  state_.shadow.technique = Technique::Msm;
  PanelActions a = draw();
  for (const char* shown : {"technique", "filter", "blur", "msm-alpha", "bleed-reduction",
                            "constant-bias", "shadow-map-size", "cascades"}) {
    EXPECT_TRUE(has(a.parameters, shown)) << "msm: " << shown;
  }
  for (const char* hidden : {"pcf-samples", "pcf-width", "esm-c", "pcss-blocker-samples",
                             "vsm-min-variance", "msm16-alpha", "soft", "light-size"}) {
    EXPECT_FALSE(has(a.parameters, hidden)) << "msm: " << hidden;
  }

  state_.shadow.technique = Technique::Pcf;
  a = draw();
  EXPECT_TRUE(has(a.parameters, "pcf-samples"));
  EXPECT_TRUE(has(a.parameters, "pcf-width"));
  EXPECT_FALSE(has(a.parameters, "blur"));
  EXPECT_FALSE(has(a.parameters, "filter"));
  EXPECT_FALSE(has(a.parameters, "msm-alpha"));

  // msm with the summed-area table: soft shadows can be had; once on,
  // the light's size and the blocker estimate apply; the summed moments
  // are biased by msm16-alpha.
  state_.shadow.technique = Technique::Msm;
  state_.shadow.filter = Filter::Sat;
  a = draw();
  EXPECT_TRUE(has(a.parameters, "soft"));
  EXPECT_FALSE(has(a.parameters, "light-size"));
  EXPECT_TRUE(has(a.parameters, "msm16-alpha"));
  EXPECT_FALSE(has(a.parameters, "msm-alpha"));
  state_.shadow.soft = true;
  a = draw();
  EXPECT_TRUE(has(a.parameters, "light-size"));
  EXPECT_TRUE(has(a.parameters, "sun-angle"));  // the default scene has a sun
  EXPECT_TRUE(has(a.parameters, "soft-two-moment-blockers"));

  state_.shadow.technique = Technique::None;
  a = draw();
  EXPECT_FALSE(has(a.parameters, "shadow-map-size"));
  EXPECT_FALSE(has(a.parameters, "constant-bias"));
}

TEST_F(PanelTest, OffersWhatAppliesToTheLights) {
  // The default scene: a spot light and a sun, no point light.
  PanelActions a = draw();
  EXPECT_TRUE(has(a.parameters, "cascades"));
  EXPECT_FALSE(has(a.parameters, "guard-band"));
  for (Light& light : state_.lights) light.type = LightType::Point;
  a = draw();
  EXPECT_FALSE(has(a.parameters, "cascades"));
  EXPECT_FALSE(has(a.parameters, "cascade-lambda"));
  EXPECT_TRUE(has(a.parameters, "guard-band"));
  state_.ssao.enabled = false;
  a = draw();
  EXPECT_FALSE(has(a.parameters, "ssao-samples"));
}

// Whatever the technique lists, the times and the command end within the
// 720-pixel display (the settings above them scroll).
TEST_F(PanelTest, TimesAndCommandStayOnA720PixelScreen) {
  for (const auto& [technique, name] : kTechniqueNames) {
    state_.shadow.technique = technique;
    const PanelActions a = draw();
    EXPECT_GT(a.status_bottom, 360.0f) << name;
    EXPECT_LE(a.status_bottom, 720.0f) << name;
  }
}

// Each GPU time is one row: the pass's whole name, then its milliseconds,
// in a line that fits the panel (nothing clipped), the frame's total last.
TEST_F(PanelTest, TimesShowPassNamesAndMilliseconds) {
  status_.gpu->pass_ms[static_cast<std::size_t>(gl::GpuPass::ShadowDepth)] = 4.25;
  status_.gpu->pass_ms[static_cast<std::size_t>(gl::GpuPass::Lighting)] = 12.5;
  status_.gpu->total_ms = 31.0;
  const PanelActions a = draw();
  ASSERT_EQ(a.timing_rows.size(), 9u);  // the 8 passes that ran, and the total
  std::size_t row = 0;
  for (std::size_t p = 0; p < status_.gpu->ran.size(); ++p) {
    if (!status_.gpu->ran[p]) continue;
    const std::string name(gl::kGpuPassNames[p]);
    EXPECT_EQ(a.timing_rows[row].rfind(name + " ", 0), 0u) << a.timing_rows[row];
    ++row;
  }
  EXPECT_EQ(a.timing_rows[0], "shadow depth               4.250 ms");
  EXPECT_EQ(a.timing_rows[7], "lighting                  12.500 ms");
  EXPECT_EQ(a.timing_rows[8], "GPU frame                 31.000 ms");
  const float inside = 400.0f - 2.0f * ImGui::GetStyle().WindowPadding.x;
  for (const std::string& text : a.timing_rows) {
    EXPECT_LE(ImGui::CalcTextSize(text.c_str()).x, inside) << text;
  }
}

// The contact shadows' own parameters are offered once they are on.
TEST(PanelRelevance, ContactShadowParametersFollowTheirSwitch) {
  ShadowSettings shadow;
  EXPECT_TRUE(parameter_applies("contact-shadows", shadow, SsaoSettings{}, {}));
  for (const char* name :
       {"contact-shadow-length", "contact-shadow-thickness", "contact-shadow-steps"}) {
    shadow.contact_shadows = false;
    EXPECT_FALSE(parameter_applies(name, shadow, SsaoSettings{}, {})) << name;
    shadow.contact_shadows = true;
    EXPECT_TRUE(parameter_applies(name, shadow, SsaoSettings{}, {})) << name;
  }
}

TEST(PanelRelevance, UnknownParametersAreShown) {
  EXPECT_TRUE(parameter_applies("a-parameter-added-later", ShadowSettings{}, SsaoSettings{}, {}));
}

}  // namespace
}  // namespace penumbra
