#include "scene/scene_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "penumbra/error.hpp"

namespace penumbra {
namespace {

const char* kValid = R"({
  "camera": {"position": [0, 5, 10], "target": [0, 0, 0], "fov": 50},
  "materials": {"red": {"albedo": [0.8, 0.1, 0.1], "shininess": 40}},
  "lights": [{"type": "spot", "position": [0, 8, 0], "target": [0, 0, 0], "cone": 30},
             {"type": "directional", "direction": [0, -1, 0.2], "intensity": 0.5}],
  "objects": [{"shape": "plane", "size": [10, 0, 10]},
              {"shape": "sphere", "radius": 1, "position": [0, 1, 0], "material": "red"}]
})";

TEST(SceneFile, ParsesAPointLight) {
  Scene s = parse_scene_json(R"({"lights": [{"type": "point", "position": [1, 2, 3],
                                            "intensity": 5}],
                                 "objects": [{"shape": "plane", "size": [4, 0, 4]}]})",
                             "point.json");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LightType::Point);
  EXPECT_EQ(s.lights[0].position, glm::vec3(1.0f, 2.0f, 3.0f));
  EXPECT_FLOAT_EQ(s.lights[0].intensity, 5.0f);
  // A point light shines every way: a direction is an unknown key.
  EXPECT_THROW(parse_scene_json(R"({"lights": [{"type": "point", "direction": [0, -1, 0]}],
                                    "objects": []})",
                                "point.json"),
               RuntimeError);
}

// Each light its own source: light_size for spot and point lights,
// sun_angle for directional ones, in their ranges; the other key refused.
TEST(SceneFile, ReadsEachLightsSourceSize) {
  const std::string plane = R"("objects": [{"shape": "plane", "size": [4, 0, 4]}]})";
  Scene s = parse_scene_json(R"({"lights": [{"type": "spot", "light_size": 0.1},
                                            {"type": "spot", "light_size": 2.5},
                                            {"type": "directional", "sun_angle": 0.53},
                                            {"type": "point"}], )" +
                                 plane,
                             "sizes.json");
  ASSERT_EQ(s.lights.size(), 4u);
  EXPECT_FLOAT_EQ(s.lights[0].light_size, 0.1f);
  EXPECT_FLOAT_EQ(s.lights[1].light_size, 2.5f);
  EXPECT_FLOAT_EQ(s.lights[2].sun_angle, 0.53f);
  EXPECT_FLOAT_EQ(s.lights[3].light_size, Light{}.light_size);
  for (const char* bad :
       {R"({"type": "spot", "light_size": -1})", R"({"type": "spot", "sun_angle": 1})",
        R"({"type": "directional", "light_size": 1})",
        R"({"type": "directional", "sun_angle": 90})"}) {
    const std::string json = std::string(R"({"lights": [)") + bad + "], " + plane;
    try {
      (void)parse_scene_json(json, "bad.json");
      ADD_FAILURE() << bad << " was read";
    } catch (const RuntimeError& e) {
      EXPECT_NE(std::string(e.what()).find("/lights/0/"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneFile, ParsesEveryKind) {
  Scene s = parse_scene_json(kValid, "test.json");
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, LightType::Spot);
  EXPECT_NEAR(s.lights[0].direction.y, -1.0f, 1e-6f);
  EXPECT_EQ(s.lights[1].type, LightType::Directional);
  ASSERT_EQ(s.shapes.size(), 2u);
  EXPECT_EQ(s.shapes[1].kind, ShapeKind::Sphere);
  EXPECT_EQ(s.materials.at(static_cast<std::size_t>(s.shapes[1].material)).name, "red");
  EXPECT_FLOAT_EQ(s.camera.fov_y_degrees, 50.0f);
}

// Each bad input names the file and the key's path.
TEST(SceneFile, ErrorsNameTheKeyPath) {
  struct Case {
    const char* json;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"lights": [{"type": "spot"}], "objects": [{"shape": "box", "colour": 1}]})",
       "bad.json: /objects/0/colour: unknown key"},
      {R"({"lights": [{"type": "spot"}], "objects": [{"shape": "sphere", "radius": -1}]})",
       "bad.json: /objects/0/radius: must be between"},
      {R"({"lights": [{"type": "lamp"}], "objects": [{"shape": "box"}]})",
       "bad.json: /lights/0/type: must be \"spot\", \"directional\" or \"point\""},
      {R"({"lights": [{"type": "spot"}], "objects": [{"shape": "box", "size": [1, 2]}]})",
       "bad.json: /objects/0/size: expected an array of 3 numbers"},
      {R"({"lights": [{"type": "spot"}], "objects": [{"shape": "box", "size": [1, "x", 2]}]})",
       "bad.json: /objects/0/size/1: expected a number"},
      {R"({"objects": [{"shape": "box"}]})", "bad.json: /lights: missing"},
      {R"({"lights": [{}], "objects": [{"shape": "box", "material": "gold"}]})",
       "bad.json: /objects/0/material: no material \"gold\""},
      {R"({"lights": [{}], "objects": [{"shape": "box"}], "extra": 1})",
       "bad.json: /extra: unknown key"},
      {R"({"lights": [{}], "objects": [)", "bad.json: not valid JSON"},
      {R"({"lights": [{}], "objects": [{"shape": "sphere", "radius": 1e400}]})",
       "bad.json: not valid JSON"},
      {R"({"camera": {"position": [0,0,0], "target": [0,0,0]}, "lights": [{}], "objects": [{"shape": "box"}]})",
       "bad.json: /camera/target: must differ from the position"},
  };
  for (const Case& c : cases) {
    try {
      parse_scene_json(c.json, "bad.json");
      ADD_FAILURE() << "accepted: " << c.json;
    } catch (const RuntimeError& e) {
      EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos)
          << "message: " << e.what() << "\nexpected: " << c.expected;
    }
  }
}

TEST(SceneFile, UnknownBuiltinNameIsAUsageError) {
  EXPECT_THROW(resolve_scene("nosuchscene"), UsageError);
  EXPECT_THROW(resolve_scene("/nonexistent/scene.json"), RuntimeError);
  EXPECT_NO_THROW(resolve_scene("default"));
  EXPECT_NO_THROW(resolve_scene("spot"));
}

}  // namespace
}  // namespace penumbra
