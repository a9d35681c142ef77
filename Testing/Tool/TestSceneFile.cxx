// The scene file of docs/reference.md: round trips, relative paths, and an error naming the key
// for each kind of bad value.
#include "vsSceneFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <cmath>
#include <functional>
#include <utility>

#include <unistd.h>

using vstool::ParseScene;
using vstool::ParseSceneText;
using vstool::Scene;
using vstool::ToJson;
using json = nlohmann::json;

namespace
{
// A complete, valid scene (every section, a procedural sun).
json FullScene()
{
  return json::parse(R"({
    "description": "test",
    "volume": {"file": "vol/ch2.nii.gz", "grid": "density"},
    "transfer_function": {
      "opacity": [[0, 0.0], [60, 0.0], [120, 0.8]],
      "color": [[0, 1, 1, 1], [255, 0.9, 0.7, 0.6]],
      "unit_distance": 1.5, "density_scale": 2.0, "interpolation": "nearest",
      "gradient_opacity": [[0, 0.0], [12.5, 1.0]]
    },
    "environment": {"sun": {"direction": [1, 0, 1], "radius_deg": 3, "radiance": [100, 90, 80], "sky": [0.1, 0.2, 0.3]},
                    "intensity": 0.5, "visible_background": false, "background": [0.1, 0.1, 0.1],
                    "octahedral_size": 64},
    "camera": {"position": [0, -400, 0], "focal_point": [90, 108, 90], "view_up": [0, 0, 1], "view_angle": 30,
               "parallel_scale": 120.25},
    "render": {"width": 320, "height": 200, "spp": 64, "strategy": "combined", "seed": 7, "exposure": 1.5,
               "tone_mapping": false, "update_scheme": "round-robin", "directions_per_frame": 8,
               "static_interval": 12, "control_extinction": "camera",
               "transmittance_estimator": "ray-marching", "sampler": "independent", "shadow_rays": 3, "mode": "preview"},
    "visibility": {"direction_resolution": 16, "voxels_per_cell": 8, "kernel_resolution": 64, "filtering": false,
                   "filter_angle_fraction": 0.25, "epsilon": 0.02, "cell_mode": "trilinear",
                   "skip_unlit_directions": false, "progressive": false, "sweep_frame_fraction": 0.5,
                   "light_weighted_directions": false, "fill_unswept": false, "extinction_pooling": 2},
    "clip_planes": [{"origin": [90, 108, 90], "normal": [1, 0, 0]}, {"origin": [0, 0, 0], "normal": [0, 0, -1]}],
    "lights": [{"type": "directional", "direction": [1, -1, 1], "focal_point": [90, 108, 90], "color": [1, 0.9, 0.8],
                "intensity": 2},
               {"type": "spot", "position": [90, -200, 90], "focal_point": [90, 108, 90], "cone_angle": 20,
                "exponent": 4, "attenuation": [0, 0, 1], "intensity": 5e4},
               {"type": "positional", "position": [0, 0, 0], "focal_point": [0, 0, -1], "follow_camera": true}]
  })");
}

// The message of the error a scene gives ("" if it parses).
std::string ErrorOf(const json& j)
{
  try
  {
    ParseScene(j, "/scenes");
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}

// Applies an edit to the full scene and returns the error message.
std::string ErrorAfter(const std::function<void(json&)>& edit)
{
  json j = FullScene();
  edit(j);
  return ErrorOf(j);
}

#define EXPECT_ERROR_STARTS(message, prefix)                                                                      \
  do                                                                                                              \
  {                                                                                                               \
    const std::string m_ = (message);                                                                             \
    EXPECT_EQ(m_.rfind(prefix, 0), 0u) << "expected an error starting with '" << (prefix) << "', got '" << m_ << "'"; \
  } while (0)
}

TEST(SceneFile, ParsesEverySection)
{
  Scene s = ParseScene(FullScene(), "/scenes");
  EXPECT_EQ(s.Volume.File, "/scenes/vol/ch2.nii.gz");
  EXPECT_EQ(s.TransferFunction.Opacity.size(), 3u);
  EXPECT_EQ(s.TransferFunction.Color[1][3], 0.6);
  EXPECT_EQ(s.TransferFunction.UnitDistance, 1.5);
  EXPECT_TRUE(s.TransferFunction.Nearest);
  ASSERT_EQ(s.TransferFunction.GradientOpacity.size(), 2u);
  EXPECT_EQ(s.TransferFunction.GradientOpacity[1][0], 12.5);
  EXPECT_EQ(s.Environment.Type, Scene::EnvironmentSection::Kind::Sun);
  EXPECT_EQ(s.Environment.SunRadiusDeg, 3.0);
  EXPECT_FALSE(s.Environment.VisibleBackground);
  EXPECT_EQ(s.Camera.ParallelScale.value(), 120.25);
  EXPECT_EQ(s.Render.Width, 320);
  EXPECT_EQ(s.Render.Strategy, "combined");
  EXPECT_EQ(vstool::StrategyIndex(s.Render.Strategy), 3);
  EXPECT_EQ(s.Render.UpdateScheme, "round-robin");
  EXPECT_EQ(vstool::UpdateSchemeIndex(s.Render.UpdateScheme), 1);
  EXPECT_EQ(s.Render.DirectionsPerFrame, 8);
  EXPECT_EQ(s.Render.StaticInterval, 12);
  EXPECT_EQ(s.Render.ControlExtinction, "camera");
  EXPECT_EQ(s.Render.TransmittanceEstimator, "ray-marching");
  EXPECT_EQ(vstool::TransmittanceEstimatorIndex(s.Render.TransmittanceEstimator), 1);
  EXPECT_EQ(s.Render.Sampler, "independent");
  EXPECT_EQ(s.Render.Mode, "preview");
  EXPECT_EQ(s.Render.ShadowRays, 3);

  EXPECT_EQ(s.Visibility.DirectionResolution.value(), 16);
  EXPECT_EQ(s.Visibility.CellMode.value(), "trilinear");
  EXPECT_FALSE(s.Visibility.SkipUnlitDirections.value());
  EXPECT_FALSE(s.Visibility.Progressive.value());
  EXPECT_EQ(s.Visibility.SweepFrameFraction.value(), 0.5);
  EXPECT_FALSE(s.Visibility.LightWeightedDirections.value());
  EXPECT_FALSE(s.Visibility.FillUnswept.value());
  EXPECT_EQ(s.Visibility.ExtinctionPooling.value(), 2);
  ASSERT_EQ(s.ClipPlanes.size(), 2u);
  EXPECT_EQ(s.ClipPlanes[1].Normal[2], -1.0);
  // issue 38: VTK's lights.
  ASSERT_EQ(s.Lights.size(), 3u);
  EXPECT_EQ(s.Lights[0].Type, "directional");
  ASSERT_TRUE(s.Lights[0].Direction.has_value());
  EXPECT_EQ((*s.Lights[0].Direction)[1], -1.0);
  EXPECT_EQ(s.Lights[0].Color[2], 0.8);
  EXPECT_EQ(s.Lights[0].Intensity, 2.0);
  EXPECT_EQ(s.Lights[1].Type, "spot");
  EXPECT_EQ(s.Lights[1].ConeAngle, 20.0);
  EXPECT_EQ(s.Lights[1].Exponent, 4.0);
  EXPECT_EQ(s.Lights[1].Attenuation[2], 1.0);
  EXPECT_FALSE(s.Lights[1].FollowCamera);
  EXPECT_EQ(s.Lights[2].Type, "positional");
  EXPECT_TRUE(s.Lights[2].FollowCamera);
  EXPECT_EQ(s.Lights[2].Attenuation[0], 1.0); // vtkLight's default
}

// issue 38: bad light keys are errors naming the key.
TEST(SceneFile, BadLights)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"] = json::object(); }), "lights: expected an array");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][1]["kind"] = "spot"; }), "lights[1].kind: unknown key");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["type"] = "area"; }), "lights[0].type: ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["intensity"] = -1; }), "lights[0].intensity: ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["color"] = { 1, 1 }; }), "lights[0].color: ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][1]["cone_angle"] = 90; }), "lights[1].cone_angle: ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][1]["exponent"] = 200; }), "lights[1].exponent: ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["cone_angle"] = 20; }),
    "lights[0].cone_angle: only for a spot light");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["attenuation"] = { 0, 0, 1 }; }),
    "lights[0].attenuation: only for a positional or spot light");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][1]["attenuation"] = { 0, 0, 0 }; }),
    "lights[1].attenuation: all three coefficients are 0");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["position"] = { 0, 0, 1 }; }),
    "lights[0].direction: give either");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][1]["direction"] = { 0, 0, 1 }; }),
    "lights[1].direction: give either");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][0]["direction"] = { 0, 0, 0 }; }),
    "lights[0].direction: the direction must not be zero");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][2]["position"] = { 0, 0, -1 }; }),
    "lights[2].position: the position is the focal point");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["lights"][2]["follow_camera"] = 1; }), "lights[2].follow_camera: ");
}

TEST(SceneFile, DefaultsOfOptionalSections)
{
  Scene s = ParseScene(json::parse(R"({
    "volume": {"file": "/data/v.vti"},
    "transfer_function": {"opacity": [[0, 0], [1, 1]]},
    "camera": {"position": [0, -10, 0], "focal_point": [0, 0, 0]}
  })"),
    "/x");
  EXPECT_EQ(s.Volume.File, "/data/v.vti");
  EXPECT_EQ(s.Volume.Grid, "density");
  EXPECT_TRUE(s.TransferFunction.Color.empty());
  EXPECT_TRUE(s.TransferFunction.GradientOpacity.empty()) << "no gradient opacity unless given";
  EXPECT_EQ(s.Environment.Type, Scene::EnvironmentSection::Kind::Constant);
  EXPECT_EQ(s.Camera.ViewUp, (vstool::Vec3{ 0, 0, 1 }));
  EXPECT_EQ(s.Camera.ViewAngle, 30.0);
  EXPECT_FALSE(s.Camera.ParallelScale.has_value());
  EXPECT_EQ(s.Render.Width, 512);
  EXPECT_EQ(s.Render.Spp, 64);
  EXPECT_EQ(s.Render.Strategy, "auto");
  EXPECT_EQ(s.Render.UpdateScheme, "round-robin"); // docs/reference.md: round-robin by default
  EXPECT_EQ(s.Render.DirectionsPerFrame, 4);
  EXPECT_EQ(s.Render.StaticInterval, 16);
  EXPECT_EQ(s.Render.ControlExtinction, "shadow");
  EXPECT_EQ(s.Render.TransmittanceEstimator, "ratio-tracking");
  EXPECT_EQ(s.Render.Sampler, "sobol");
  EXPECT_EQ(s.Render.Mode, "monte-carlo");
  EXPECT_EQ(s.Render.ShadowRays, 1);

  EXPECT_FALSE(s.Visibility.DirectionResolution.has_value());
  EXPECT_TRUE(s.ClipPlanes.empty());
}

TEST(SceneFile, CameraIsOptional)
{
  // Without "camera" the renderer frames the volume (ResetCamera) looking along +Y, +Z up.
  json file = FullScene();
  file.erase("camera");
  const Scene s = ParseScene(file, "/x");
  EXPECT_TRUE(s.Camera.Reset);
  EXPECT_EQ(s.Camera.Position, (vstool::Vec3{ 0, -1, 0 }));
  EXPECT_EQ(s.Camera.FocalPoint, (vstool::Vec3{ 0, 0, 0 }));
  EXPECT_EQ(s.Camera.ViewUp, (vstool::Vec3{ 0, 0, 1 }));
  EXPECT_FALSE(ToJson(s).contains("camera"));
  EXPECT_EQ(ParseScene(ToJson(s), "/x"), s);
  EXPECT_FALSE(ParseScene(FullScene(), "/x").Camera.Reset);
}

TEST(SceneFile, StrategiesInTheApiSpellingToo)
{
  // The mapper's names (SetSamplingStrategyToTwoStep) work as well as the scene file's.
  EXPECT_EQ(vstool::StrategyIndex("two-step"), 4);
  EXPECT_EQ(vstool::StrategyIndex("TwoStep"), 4);
  EXPECT_EQ(vstool::StrategyIndex("two_step"), 4);
  EXPECT_EQ(vstool::StrategyIndex("Uniform"), 0);
  EXPECT_EQ(vstool::StrategyIndex("ENVIRONMENT"), 1);
  EXPECT_THROW(vstool::StrategyIndex("two step"), std::runtime_error);
  EXPECT_THROW(vstool::StrategyIndex("TwoSteps"), std::runtime_error);
  json file = FullScene();
  file["render"]["strategy"] = "TwoStep";
  EXPECT_EQ(ParseScene(file, "/x").Render.Strategy, "two-step"); // stored in the file's spelling
}

// Issue 35: every word in the API's spelling, not only the strategies (render.mode refused "Preview").
TEST(SceneFile, WordsInTheApiSpellingToo)
{
  json file = FullScene();
  file["render"]["mode"] = "Preview";
  EXPECT_EQ(ParseScene(file, "/x").Render.Mode, "preview");
  file["render"]["mode"] = "AmbientOcclusion";
  EXPECT_EQ(ParseScene(file, "/x").Render.Mode, "ambient-occlusion");
  file["render"]["update_scheme"] = "RoundRobin";
  EXPECT_EQ(ParseScene(file, "/x").Render.UpdateScheme, "round-robin");
  EXPECT_EQ(vstool::RenderModeIndex("MonteCarlo"), vstool::RenderModeIndex("monte-carlo"));
  EXPECT_THROW(vstool::RenderModeIndex("Monte Carlo"), std::runtime_error);
}

TEST(SceneFile, RoundTrip)
{
  // Every environment kind, and with/without the optional sections.
  std::vector<json> scenes;
  scenes.push_back(FullScene());
  json file = FullScene();
  file["environment"] = json::parse(R"({"file": "../env/sunrise.exr", "rotation_deg": 90.5, "intensity": 2})");
  file.erase("visibility");
  file.erase("clip_planes");
  file["camera"].erase("parallel_scale");
  scenes.push_back(file);
  json constant = FullScene();
  constant["environment"] = json::parse(R"({"constant": [0.5, 0.25, 1e-3]})");
  constant["transfer_function"].erase("color");
  scenes.push_back(constant);
  json twoTone = FullScene();
  twoTone["environment"] = json::parse(R"({"two_tone": {"upper": [1, 1, 1], "lower": [0.1, 0.2, 0.3]}})");
  twoTone["volume"] = json::parse(R"({"files": ["a_0001.vdb", "a_0002.vdb"], "grid": "smoke", "time_step": 1})");
  twoTone["visibility"] = json::parse(R"({"epsilon": 0.1})");
  scenes.push_back(twoTone);
  // Values that do not print exactly in few digits.
  json awkward = FullScene();
  awkward["camera"]["position"] = { 0.1, -1.0 / 3.0, 1e-17 };
  awkward["transfer_function"]["opacity"] = { { -1024.5, 0.0 }, { 0.1, 1.0 / 7.0 }, { 3071, 1.0 } };
  scenes.push_back(awkward);

  for (const auto& j : scenes)
  {
    Scene s = ParseScene(j, "/scenes/a");
    const json out = ToJson(s);
    Scene back = ParseScene(out, "/somewhere/else"); // paths are absolute after parsing
    EXPECT_TRUE(back == s) << out.dump(2);
    EXPECT_EQ(ToJson(back), out);
    // and through text
    Scene text = ParseSceneText(out.dump(), "/elsewhere");
    EXPECT_TRUE(text == s);
  }
}

TEST(SceneFile, EqualityNoticesChanges)
{
  Scene a = ParseScene(FullScene(), "/s");
  Scene b = a;
  EXPECT_TRUE(a == b);
  b.Render.Seed = 8;
  EXPECT_FALSE(a == b);
  b = a;
  b.Visibility.Epsilon.reset();
  EXPECT_FALSE(a == b);
  b = a;
  b.Environment.SunSky[1] = 0.0;
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.UpdateScheme = "static";
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.StaticInterval = 3;
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.ControlExtinction = "both";
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.TransmittanceEstimator = a.Render.TransmittanceEstimator == "ray-marching" ? "ratio-tracking" : "ray-marching";
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.Sampler = a.Render.Sampler == "sobol" ? "independent" : "sobol";
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.Mode = a.Render.Mode == "preview" ? "monte-carlo" : "preview";
  EXPECT_FALSE(a == b);
  b = a;
  b.Render.ShadowRays = a.Render.ShadowRays + 1;
  EXPECT_FALSE(a == b);
  b = a;
  b.Lights[1].ConeAngle = 25.0;
  EXPECT_FALSE(a == b);
  b = a;
  b.Lights[2].FollowCamera = false;
  EXPECT_FALSE(a == b);
}

TEST(SceneFile, RelativePathsResolveAgainstTheSceneFolder)
{
  Scene s = ParseScene(json::parse(R"({
    "volume": {"file": "../volumes/./head.nii.gz"},
    "transfer_function": {"opacity": [[0, 0], [1, 1]]},
    "environment": {"file": "env/forest.exr"},
    "camera": {"position": [0, -10, 0], "focal_point": [0, 0, 0]}
  })"),
    "/data/scenes");
  EXPECT_EQ(s.Volume.File, "/data/volumes/head.nii.gz");
  EXPECT_EQ(s.Environment.File, "/data/scenes/env/forest.exr");

  // ReadSceneFile uses the file's own folder, even when given a relative name.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("vissweep_scene_test_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  const fs::path file = dir / "sub" / "scene.json";
  {
    std::ofstream out(file);
    out << R"({"volume": {"files": ["f1.vdb", "/abs/f2.vdb"]}, "transfer_function": {"opacity": [[0, 0]]},
              "camera": {"position": [0, -10, 0], "focal_point": [0, 0, 0]}})";
  }
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);
  Scene r = vstool::ReadSceneFile("sub/scene.json");
  fs::current_path(cwd);
  ASSERT_EQ(r.Volume.Files.size(), 2u);
  EXPECT_EQ(r.Volume.Files[0], (fs::absolute(dir) / "sub" / "f1.vdb").lexically_normal().string());
  EXPECT_EQ(r.Volume.Files[1], "/abs/f2.vdb");
  fs::remove_all(dir);
}

// A directory used to read as an empty file: "invalid JSON ... unexpected end of input".
TEST(SceneFile, DirectoryIsNamedAsADirectory)
{
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("vissweep-scene-dir-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  try
  {
    vstool::ReadSceneFile(dir.string());
    FAIL() << "no error";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(SceneFile, FileErrorsNameTheFile)
{
  try
  {
    vstool::ReadSceneFile("/nonexistent/scene.json");
    FAIL() << "no error";
  }
  catch (const std::runtime_error& e)
  {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.json"), std::string::npos) << e.what();
  }
  try
  {
    ParseSceneText("{\"volume\": {\"file\": \"a.vti\"},\n \"camera\": [1, 2,,]}", "/");
    FAIL() << "no error";
  }
  catch (const std::runtime_error& e)
  {
    const std::string m = e.what();
    EXPECT_NE(m.find("invalid JSON"), std::string::npos) << m;
    EXPECT_NE(m.find("line 2"), std::string::npos) << m;
  }
}

// Found by the fuzz target: a number literal beyond the range of a double made nlohmann-json
// throw out_of_range (not parse_error), which escaped ParseSceneText as a non-runtime_error
// (and ReadSceneFile then did not name the file).
TEST(SceneFile, NumberOverflowIsAnInvalidJsonError)
{
  for (const char* text : { "{\"render\": {\"spp\": 1e999}}", "99.99899E98899", "[-1e400]" })
  {
    try
    {
      ParseSceneText(text, "/");
      FAIL() << "no error for " << text;
    }
    catch (const std::runtime_error& e)
    {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("invalid JSON: ", 0), 0u) << m;
      EXPECT_NE(m.find("number overflow"), std::string::npos) << m;
    }
  }
}

TEST(SceneFile, UnknownKeysNameTheKey)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["rendr"] = json::object(); }), "rendr: unknown key (expected ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["sample"] = 4; }), "render.sample: unknown key");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["sun"]["power"] = 4; }),
    "environment.sun.power: unknown key");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["clip_planes"][1]["offset"] = 4; }),
    "clip_planes[1].offset: unknown key");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["visibility"]["resolution"] = 8; }),
    "visibility.resolution: unknown key");
  // the message lists what is allowed
  const std::string m = ErrorAfter([](json& j) { j["camera"]["fov"] = 30; });
  EXPECT_NE(m.find("view_angle"), std::string::npos) << m;
}

TEST(SceneFile, MissingRequiredKeys)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j.erase("volume"); }), "volume: missing required key");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["volume"].erase("file"); }), "volume.file: missing required key");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j.erase("transfer_function"); }), "transfer_function: missing");
  EXPECT_ERROR_STARTS(
    ErrorAfter([](json& j) { j["transfer_function"].erase("opacity"); }), "transfer_function.opacity: missing");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"].erase("position"); }), "camera.position: missing");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"].erase("focal_point"); }), "camera.focal_point: missing");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["sun"].erase("direction"); }),
    "environment.sun.direction: missing");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"] = json::parse(R"({"intensity": 1})"); }),
    "environment: missing a source");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["clip_planes"][0].erase("normal"); }),
    "clip_planes[0].normal: missing");
}

TEST(SceneFile, WrongTypes)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["width"] = "512"; }),
    "render.width: expected an integer, got string");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["spp"] = 2.5; }), "render.spp: expected an integer");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["strategy"] = 4; }),
    "render.strategy: expected a string, got number");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["visible_background"] = 1; }),
    "environment.visible_background: expected true or false");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["view_angle"] = json::array({ 30 }); }),
    "camera.view_angle: expected a number, got array");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"] = 3; }), "camera: expected an object, got number");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["position"][1] = "x"; }),
    "camera.position[1]: expected a number, got string");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["volume"]["file"] = nullptr; }),
    "volume.file: expected a string, got null");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["clip_planes"] = json::object(); }), "clip_planes: expected an array");
  EXPECT_ERROR_STARTS(ErrorOf(json::array()), "scene: expected an object");
  // an integral float is accepted as an integer
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["width"] = 256.0; }), "");
}

TEST(SceneFile, BadValues)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["width"] = -5; }), "render.width: width -5 not in [1, ");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["height"] = 0; }), "render.height: height 0 not in");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["spp"] = 0; }), "render.spp: samples per pixel 0");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["seed"] = -1; }), "render.seed: seed -1 not in");
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["strategy"] = "foo"; }),
    "render.strategy: unknown strategy 'foo' (expected uniform, environment, visibility, combined, two-step, auto)");
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["mode"] = "fast"; }),
    "render.mode: unknown render mode 'fast' (expected emission-absorption, monte-carlo, preview, ambient-occlusion)");
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["sampler"] = "halton"; }),
    "render.sampler: unknown sampler 'halton' (expected independent, sobol)");
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["control_extinction"] = "residual"; }),
    "render.control_extinction: unknown control extinction 'residual' (expected none, shadow, camera, both)");
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["transmittance_estimator"] = "delta"; }),
    "render.transmittance_estimator: unknown transmittance estimator 'delta' (expected ratio-tracking, ray-marching)");
  EXPECT_EQ(ErrorAfter([](json& j) { j["render"]["update_scheme"] = "lazy"; }),
    "render.update_scheme: unknown update scheme 'lazy' (expected full, round-robin, environment-guided, static)");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["update_scheme"] = 1; }),
    "render.update_scheme: expected a string, got number");
  // Issue 35: voxels_per_cell outside what the mapper uses is refused, not clamped silently.
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["visibility"]["voxels_per_cell"] = 1e30; }),
    "visibility.voxels_per_cell: voxels per cell 1e+30 not in [1, 256]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["visibility"]["voxels_per_cell"] = 0.001; }),
    "visibility.voxels_per_cell: voxels per cell 0.001 not in [1, 256]");
  EXPECT_EQ(ErrorAfter([](json& j) { j["visibility"]["voxels_per_cell"] = 256; }), "");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["directions_per_frame"] = 0; }),
    "render.directions_per_frame: directions per frame 0 not in [1, 4096]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["shadow_rays"] = 65; }),
    "render.shadow_rays: shadow rays per scatter point 65 not in [1, 64]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["render"]["static_interval"] = 1.5; }),
    "render.static_interval: expected an integer");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["opacity"][2][1] = 1.5; }),
    "transfer_function.opacity[2][1]: opacity 1.5 not in [0, 1]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["opacity"][0][1] = -0.1; }),
    "transfer_function.opacity[0][1]: opacity -0.1 not in [0, 1]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["color"][1][2] = 2; }),
    "transfer_function.color[1][2]: albedo 2 not in [0, 1]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["unit_distance"] = 0; }),
    "transfer_function.unit_distance: the unit distance must be positive");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["density_scale"] = -1; }),
    "transfer_function.density_scale: the density scale must not be negative");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["interpolation"] = "cubic"; }),
    "transfer_function.interpolation: unknown interpolation 'cubic' (expected linear, nearest)");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["intensity"] = -2; }),
    "environment.intensity: the intensity must not be negative");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["background"][0] = -1; }),
    "environment.background[0]: colour must not be negative");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["sun"]["radius_deg"] = 200; }),
    "environment.sun.radius_deg: radius 200 not in [0, 180]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["sun"]["direction"] = { 0, 0, 0 }; }),
    "environment.sun.direction: the direction must not be zero");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["octahedral_size"] = 48; }),
    "environment.octahedral_size: size 48 is not a power of two");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["rotation_deg"] = 10; }),
    "environment.rotation_deg: only for an environment 'file'");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["file"] = "x.exr"; }),
    "environment: give only one of");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["view_angle"] = 180; }),
    "camera.view_angle: angle 180 not in (0, 180)");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["focal_point"] = j["camera"]["position"]; }),
    "camera.focal_point: the focal point equals the position");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["view_up"] = { 90, 508, 90 }; }),
    "camera.view_up: parallel to the view direction");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["parallel_scale"] = -1; }),
    "camera.parallel_scale: the parallel scale must be positive");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["visibility"]["direction_resolution"] = 6; }),
    "visibility.direction_resolution: resolution 6 is not 4, 8 or 16");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["visibility"]["filter_angle_fraction"] = 1.2; }),
    "visibility.filter_angle_fraction: fraction 1.2 not in [0, 1]");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["visibility"]["cell_mode"] = "nearest"; }),
    "visibility.cell_mode: unknown cell mode 'nearest'");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["clip_planes"][0]["normal"] = { 0, 0, 0 }; }),
    "clip_planes[0].normal: the direction must not be zero");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["volume"]["file"] = ""; }), "volume.file: empty file name");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["volume"]["files"] = json::array({ "a.vdb" }); }),
    "volume: give either 'file' or 'files'");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["volume"]["time_step"] = 0; }),
    "volume.time_step: only for a sequence");
}

// Issue 13, item 5: finite doubles the renderer's float cannot hold are refused, naming the key and
// the limit (they used to become infinities or zeros on the device: an all-NaN image, an empty
// transfer function, an ignored plane). Directions are only ways: (1e300, 0, 0) is +X.
TEST(SceneFile, NumbersOutsideFloatRangeAreRefused)
{
  const std::string limit = "is outside the range of float, which the renderer computes in (magnitude at most 3.40282e+38)";
  const std::pair<std::function<void(json&)>, std::string> cases[] = {
    { [](json& j) { j["environment"]["intensity"] = 1e39; }, "environment.intensity: 1e+39 " + limit },
    { [](json& j) { j["environment"]["sun"]["radiance"][1] = 5e38; }, "environment.sun.radiance[1]: 5e+38 " + limit },
    { [](json& j) { j["environment"]["background"][2] = 1e300; }, "environment.background[2]: 1e+300 " + limit },
    { [](json& j) { j["transfer_function"]["opacity"][2][0] = 1e39; },
      "transfer_function.opacity[2][0]: 1e+39 " + limit },
    { [](json& j) { j["transfer_function"]["opacity"][0][0] = -1e39; },
      "transfer_function.opacity[0][0]: -1e+39 " + limit },
    { [](json& j) { j["transfer_function"]["color"][1][0] = 4e38; }, "transfer_function.color[1][0]: 4e+38 " + limit },
    { [](json& j) { j["transfer_function"]["density_scale"] = 1e40; },
      "transfer_function.density_scale: 1e+40 " + limit },
    { [](json& j) { j["camera"]["position"][0] = -1e39; }, "camera.position[0]: -1e+39 " + limit },
    { [](json& j) { j["camera"]["focal_point"][2] = 1e300; }, "camera.focal_point[2]: 1e+300 " + limit },
    { [](json& j) { j["render"]["exposure"] = 1e39; }, "render.exposure: 1e+39 " + limit },
    { [](json& j) { j["clip_planes"][1]["origin"][1] = 1e39; }, "clip_planes[1].origin[1]: 1e+39 " + limit },
    { [](json& j) { j["transfer_function"]["unit_distance"] = 1e-40; },
      "transfer_function.unit_distance: the unit distance 1e-40 is outside the range of float, which the renderer "
      "computes in (between 1.17549e-38 and 3.40282e+38)" },
    { [](json& j) { j["transfer_function"]["unit_distance"] = 1e39; },
      "transfer_function.unit_distance: the unit distance 1e+39 is outside the range of float" },
    { [](json& j) { j["camera"]["parallel_scale"] = 1e-39; },
      "camera.parallel_scale: the parallel scale 1e-39 is outside the range of float" },
    { [](json& j) { j["camera"]["parallel_scale"] = 1e39; },
      "camera.parallel_scale: the parallel scale 1e+39 is outside the range of float" },
  };
  for (const auto& c : cases)
  {
    EXPECT_ERROR_STARTS(ErrorAfter(c.first), c.second);
  }
  // At the limits: accepted.
  EXPECT_EQ(ErrorAfter([](json& j) {
    j["environment"]["intensity"] = 3.4e38;
    j["transfer_function"]["unit_distance"] = 1.2e-38;
    j["transfer_function"]["opacity"][0][0] = -3.4e38;
    j["camera"]["parallel_scale"] = 3.4e38;
  }),
    "");
  // Huge and tiny directions are directions: the sun, the view up and a clip-plane normal.
  EXPECT_EQ(ErrorAfter([](json& j) {
    j["environment"]["sun"]["direction"] = { 1e300, 0, 1e300 };
    j["camera"]["view_up"] = { 0, 0, 1e-300 };
    j["clip_planes"][0]["normal"] = { 1e300, 0, 0 };
  }),
    "");
  const vstool::Vec3 n = vstool::Normalized({ 1e300, 0, -1e300 });
  EXPECT_DOUBLE_EQ(n[0], std::sqrt(0.5));
  EXPECT_EQ(n[1], 0.0);
  EXPECT_DOUBLE_EQ(n[2], -std::sqrt(0.5));
  const vstool::Vec3 t = vstool::Normalized({ 0, 1e-310, 0 });
  EXPECT_EQ(t[1], 1.0);
  // Still a view up parallel to the view direction when tiny.
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["view_up"] = { 90e-300, 508e-300, 90e-300 }; }),
    "camera.view_up: parallel to the view direction");
}

TEST(SceneFile, UnsortedTransferFunctions)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["opacity"] = { { 0, 0 }, { 80, 0.3 }, { 40, 0.1 } }; }),
    "transfer_function.opacity[2][0]: scalar 40 does not follow 80 (points must be sorted");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["color"] = { { 5, 1, 1, 1 }, { 5, 0, 0, 0 } }; }),
    "transfer_function.color[1][0]: scalar 5 does not follow 5");
  EXPECT_ERROR_STARTS(
    ErrorAfter([](json& j) { j["transfer_function"]["gradient_opacity"] = { { 2, 0 }, { 1, 1 } }; }),
    "transfer_function.gradient_opacity[1][0]: gradient magnitude 1 does not follow 2");
  EXPECT_ERROR_STARTS(
    ErrorAfter([](json& j) { j["transfer_function"]["gradient_opacity"] = { { -1, 0 }, { 1, 1 } }; }),
    "transfer_function.gradient_opacity[0][0]: ");
  EXPECT_ERROR_STARTS(
    ErrorAfter([](json& j) { j["transfer_function"]["gradient_opacity"] = { { 0, 0 }, { 1, 1.5 } }; }),
    "transfer_function.gradient_opacity[1][1]: ");
}

TEST(SceneFile, WrongArrayLengths)
{
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["camera"]["position"] = { 0, 1 }; }),
    "camera.position: expected an array of 3 numbers, got 2 elements");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["environment"]["background"] = { 0, 0, 0, 1 }; }),
    "environment.background: expected an array of 3 numbers, got 4 elements");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["opacity"][1] = { 60, 0.0, 1 }; }),
    "transfer_function.opacity[1]: expected an array of 2 numbers, got 3 elements");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["color"][0] = { 0, 1, 1 }; }),
    "transfer_function.color[0]: expected an array of 4 numbers, got 3 elements");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["transfer_function"]["opacity"] = json::array(); }),
    "transfer_function.opacity: expected a non-empty array");
  EXPECT_ERROR_STARTS(ErrorAfter([](json& j) { j["volume"] = json::parse(R"({"files": []})"); }),
    "volume.files: expected a non-empty array");
}

TEST(SceneFile, ExampleScenesParse)
{
  namespace fs = std::filesystem;
  int count = 0;
  for (const auto& entry : fs::directory_iterator(VISSWEEP_EXAMPLE_SCENES))
  {
    if (entry.path().extension() != ".json")
    {
      continue;
    }
    ++count;
    SCOPED_TRACE(entry.path().string());
    Scene s;
    ASSERT_NO_THROW(s = vstool::ReadSceneFile(entry.path().string()));
    if (s.Volume.Files.empty())
    {
      EXPECT_TRUE(fs::exists(s.Volume.File)) << s.Volume.File;
    }
    for (const auto& f : s.Volume.Files) // a sequence: every step must exist
    {
      EXPECT_TRUE(fs::exists(f)) << f;
    }
    if (s.Environment.Type == Scene::EnvironmentSection::Kind::File)
    {
      EXPECT_TRUE(fs::exists(s.Environment.File)) << s.Environment.File;
    }
    EXPECT_TRUE(vstool::ParseScene(ToJson(s), "/") == s);
  }
  EXPECT_GE(count, 3);
}
