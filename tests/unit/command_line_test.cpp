// "Copy as command": the arguments written for a view read back through the
// CLI's own registration as exactly the settings, camera and lights shown.
#include "app/command_line.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "app/render_command.hpp"
#include "penumbra/error.hpp"
#include "scene/builtin_scenes.hpp"

namespace penumbra {
namespace {

// Parses `args` (after the program name) as the CLI does and applies them.
RenderArgs parse(const std::vector<std::string>& args, Scene* scene = nullptr) {
  CLI::App app;
  RenderArgs parsed;
  CLI::App* render = app.add_subcommand("render");
  add_render_command_options(*render, parsed);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  app.parse(reversed);
  parse_named_options(parsed.named, parsed.shadow, parsed.render);
  if (scene != nullptr)
    apply_scene_options(parsed.scene_options, parsed.render.light_index, *scene);
  return parsed;
}

void expect_same_light(const Light& a, const Light& b) {
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_EQ(a.color, b.color);
  EXPECT_EQ(a.intensity, b.intensity);
  EXPECT_EQ(a.cone_degrees, b.cone_degrees);
}

TEST(CommandLine, DefaultsGiveTheShortestCommand) {
  const Scene scene = *builtin_scene("default");
  const std::vector<std::string> args = render_command_args({.scene_argument = "default",
                                                             .model_argument = "",
                                                             .light = {},
                                                             .render = {},
                                                             .shadow = {},
                                                             .ssao = {},
                                                             .original = &scene,
                                                             .edited = &scene,
                                                             .output = "a.png"});
  EXPECT_EQ(args, (std::vector<std::string>{"render", "--output=a.png"}));
}

TEST(CommandLine, AModelReplacesTheScene) {
  const std::vector<std::string> args = render_command_args({.scene_argument = "spot",
                                                             .model_argument = "models/bunny.obj",
                                                             .light = {},
                                                             .render = {},
                                                             .shadow = {},
                                                             .ssao = {},
                                                             .original = nullptr,
                                                             .edited = nullptr,
                                                             .output = "a.png"});
  EXPECT_EQ(args,
            (std::vector<std::string>{"render", "--model=models/bunny.obj", "--output=a.png"}));
}

// A glTF scene's camera chosen with --camera-index is part of the command
// (the viewer's "Copy as command" re-renders from the same camera).
TEST(CommandLine, KeepsAGltfScenesCameraIndex) {
  const std::vector<std::string> args = render_command_args({.scene_argument = "scene.gltf",
                                                             .model_argument = {},
                                                             .light = {},
                                                             .camera_index = 1,
                                                             .render = {},
                                                             .shadow = {},
                                                             .ssao = {},
                                                             .original = nullptr,
                                                             .edited = nullptr,
                                                             .output = "a.png"});
  EXPECT_EQ(args, (std::vector<std::string>{"render", "--scene=scene.gltf", "--camera-index=1",
                                            "--output=a.png"}));
}

TEST(CommandLine, ReadsBackAsTheSameSettingsCameraAndLights) {
  const Scene original = *builtin_scene("default");
  ASSERT_GE(original.lights.size(), 2u);
  Scene edited = original;
  edited.camera.position = {-3.1234567f, 4.5f, 7.0000001f};
  edited.camera.target = {0.1f, -0.2f, 1e-7f};
  edited.camera.fov_y_degrees = 60.0f;
  edited.lights[0].position = {-2.0f, 7.25f, 1.0f / 3.0f};
  edited.lights[0].direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.1f));
  edited.lights[0].cone_degrees = 22.5f;
  edited.lights[1].color = {1.0f, 0.5f, 0.25f};
  edited.lights[1].direction = glm::normalize(glm::vec3(-0.7f, -0.6f, 0.2f));

  RenderSettings render;
  render.width = 333;
  render.height = 111;
  render.view = View::MomentsFiltered;
  render.light_index = 1;
  ShadowSettings shadow;
  shadow.technique = Technique::Msm16;
  shadow.filter = Filter::Sat;
  shadow.soft = true;
  shadow.blur = 9;
  shadow.map_size = 1024;
  shadow.msm16_alpha = 3.3e-5f;
  shadow.constant_bias = 0.0f;
  shadow.light_size = 0.1f + 0.2f;
  shadow.guard_band = false;
  shadow.cascades = 2;
  shadow.cascade_lambda = 0.5f;

  const std::vector<std::string> args = render_command_args({.scene_argument = "default",
                                                             .model_argument = "",
                                                             .light = {},
                                                             .render = render,
                                                             .shadow = shadow,
                                                             .ssao = {},
                                                             .original = &original,
                                                             .edited = &edited,
                                                             .output = "out dir/shot.png"});
  Scene scene = original;
  const RenderArgs parsed = parse(args, &scene);
  EXPECT_EQ(parsed.output, "out dir/shot.png");
  EXPECT_EQ(parsed.scene, "default");
  EXPECT_EQ(parsed.render.width, render.width);
  EXPECT_EQ(parsed.render.height, render.height);
  EXPECT_EQ(parsed.render.view, render.view);
  EXPECT_EQ(parsed.render.light_index, render.light_index);
  for (const auto& p : kShadowFloatParams) {
    EXPECT_EQ(parsed.shadow.*(p.field), shadow.*(p.field)) << p.name;
  }
  for (const auto& p : kShadowIntParams) {
    EXPECT_EQ(parsed.shadow.*(p.field), shadow.*(p.field)) << p.name;
  }
  // Given, --light-size is set for every light; --sun-angle, not given, is not.
  EXPECT_TRUE(parsed.shadow.light_size.is_set());
  EXPECT_EQ(parsed.shadow.light_size, shadow.light_size);
  EXPECT_FALSE(parsed.shadow.sun_angle.is_set());
  for (const auto& p : kShadowFlagParams) {
    EXPECT_EQ(parsed.shadow.*(p.field), shadow.*(p.field)) << p.name;
  }
  for (const auto& p : kShadowSwitchParams) {
    EXPECT_EQ(parsed.shadow.*(p.field), shadow.*(p.field)) << p.name;
  }
  EXPECT_EQ(parsed.shadow.technique, shadow.technique);
  EXPECT_EQ(parsed.shadow.filter, shadow.filter);
  EXPECT_EQ(scene.camera.position, edited.camera.position);
  EXPECT_EQ(scene.camera.target, edited.camera.target);
  EXPECT_EQ(scene.camera.fov_y_degrees, edited.camera.fov_y_degrees);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    SCOPED_TRACE(i);
    expect_same_light(scene.lights[i], edited.lights[i]);
  }
  // Light 0 is not --light-index, so its flags name it.
  EXPECT_NE(std::find(args.begin(), args.end(), "--light-cone=0:22.5"), args.end());
}

// Every on/off parameter changed from its default is written "--name" or
// "--no-name", and reads back.
TEST(CommandLine, SwitchesReadBackInBothSpellings) {
  ShadowSettings shadow;
  shadow.technique = Technique::Msm;
  shadow.filter = Filter::Sat;
  shadow.soft = true;
  shadow.soft_two_moment_blockers = true;
  shadow.guard_band = false;
  SsaoSettings ssao;
  ssao.enabled = false;
  ssao.half_resolution = true;
  const std::vector<std::string> args = render_command_args({.scene_argument = "default",
                                                             .model_argument = "",
                                                             .light = {},
                                                             .render = {},
                                                             .shadow = shadow,
                                                             .ssao = ssao,
                                                             .original = nullptr,
                                                             .edited = nullptr,
                                                             .output = "a.png"});
  for (const char* expected : {"--soft", "--soft-two-moment-blockers", "--no-guard-band",
                               "--no-ssao", "--ssao-half-resolution"}) {
    EXPECT_NE(std::find(args.begin(), args.end(), expected), args.end()) << expected;
  }
  const RenderArgs parsed = parse(args);
  EXPECT_TRUE(parsed.shadow.soft);
  EXPECT_TRUE(parsed.shadow.soft_two_moment_blockers);
  EXPECT_FALSE(parsed.shadow.guard_band);
  EXPECT_FALSE(parsed.ssao.enabled);
  EXPECT_TRUE(parsed.ssao.half_resolution);
}

TEST(CommandLine, ShellCommandQuotesWhatTheShellWouldSplit) {
  EXPECT_EQ(shell_command({"render", "--output=a b.png", "--light-position=-1,2,3"}),
            "penumbra render '--output=a b.png' --light-position=-1,2,3");
  EXPECT_EQ(shell_command({"render", "--scene=it's.json"}),
            "penumbra render '--scene=it'\\''s.json'");
}

TEST(SceneOptions, NegativeNumbersReadAsValuesWithoutEquals) {
  Scene scene = *builtin_scene("default");
  parse({"render", "--light-position", "-1,2,-3", "--camera-target", "-0.5,0,0", "-o", "x.png"},
        &scene);
  EXPECT_EQ(scene.lights[0].position, glm::vec3(-1.0f, 2.0f, -3.0f));
  EXPECT_EQ(scene.camera.target, glm::vec3(-0.5f, 0.0f, 0.0f));
}

TEST(SceneOptions, BadValuesNameTheFlag) {
  const auto error = [](const std::vector<std::string>& flags) -> std::string {
    Scene scene = *builtin_scene("default");
    std::vector<std::string> args{"render"};
    args.insert(args.end(), flags.begin(), flags.end());
    args.insert(args.end(), {"-o", "x.png"});
    try {
      parse(args, &scene);
    } catch (const UsageError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(error({"--light-position=1,2"}).find("--light-position"), std::string::npos);
  EXPECT_NE(error({"--light-position=1,2,x"}).find("'x'"), std::string::npos);
  EXPECT_NE(error({"--light-position=1,2,3,4"}).find("three numbers"), std::string::npos);
  EXPECT_NE(error({"--light-direction=0,0,0"}).find("--light-direction"), std::string::npos);
  EXPECT_NE(error({"--light-color=-1,0,0"}).find("negative"), std::string::npos);
  EXPECT_NE(error({"--light-cone=95"}).find("--light-cone"), std::string::npos);
  EXPECT_NE(error({"--light-intensity=nan"}).find("finite"), std::string::npos);
  EXPECT_NE(error({"--light-position=7:1,2,3"}).find("no light 7"), std::string::npos);
  EXPECT_NE(error({"--light-position=x:1,2,3"}).find("light index"), std::string::npos);
  // Light 1 of the default scene is the sun.
  EXPECT_NE(error({"--light-position=1:1,2,3"}).find("directional"), std::string::npos);
  EXPECT_NE(error({"--camera-position=1,1,1", "--camera-target=1,1,1"}).find("same point"),
            std::string::npos);
  EXPECT_NE(error({"--camera-fov=0"}).find("--camera-fov"), std::string::npos);
}

TEST(CommandLine, NamesTheLightChoice) {
  const Scene scene = *builtin_scene("default");
  const std::vector<std::string> args = render_command_args({.scene_argument = "default",
                                                             .model_argument = "",
                                                             .light = "point",
                                                             .render = {},
                                                             .shadow = {},
                                                             .ssao = {},
                                                             .original = &scene,
                                                             .edited = &scene,
                                                             .output = "a.png"});
  EXPECT_EQ(args, (std::vector<std::string>{"render", "--light=point", "--output=a.png"}));
}

}  // namespace
}  // namespace penumbra
