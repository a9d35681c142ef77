// vsSceneFile.cxx — parsing a scene file into a Scene (vsSceneFile.h): each section by its own
// function, errors naming the key path.
#include "vsSceneFile.h"
#include "vsSceneValues.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace vstool
{
using json = nlohmann::json;

using namespace sceneio;

namespace
{
// A transfer function's points [x, y...]: x strictly increasing (at least 0 when xNonNegative
// names it) and within float's range, each y within the schema entry's range.
template <size_t N>
std::vector<std::array<double, N>> Points(const SceneSection& tf, const std::string& name, const std::string& shape,
  const std::string& x, const std::string& xs, const char* xNonNegative = nullptr)
{
  const SceneKey& e = tf.Entry(name);
  const std::string path = tf.Key(name);
  const json& v = tf[name];
  if (!v.is_array() || v.empty())
  {
    Fail(path, "expected a non-empty array of " + shape + " points");
  }
  std::vector<std::array<double, N>> points;
  for (size_t i = 0; i < v.size(); ++i)
  {
    const std::string key = At(path, i);
    auto p = Numbers<N>(v[i], key);
    FitsFloat(xNonNegative ? NonNegative(v[i][0], At(key, 0), xNonNegative) : p[0], At(key, 0));
    for (size_t k = 1; k < N; ++k)
    {
      NumberIn(v[i][k], At(key, k), e.Min, e.Max, e.Noun);
    }
    if (!points.empty() && !(p[0] > points.back()[0]))
    {
      Fail(At(key, 0), x + " " + Num(p[0]) + " does not follow " + Num(points.back()[0]) +
          " (points must be sorted by increasing " + xs + ")");
    }
    points.push_back(p);
  }
  return points;
}

Scene::VolumeSection ParseVolume(const json& value, const std::string& baseDir)
{
  const SceneSection v(value, "volume");
  Scene::VolumeSection s;
  if (v.Has("file") && v.Has("files"))
  {
    Fail("volume", "give either 'file' or 'files', not both");
  }
  if (v.Has("file"))
  {
    s.File = v.File("file", baseDir);
  }
  else if (v.Has("files"))
  {
    const json& f = v["files"];
    if (!f.is_array() || f.empty())
    {
      Fail("volume.files", "expected a non-empty array of file names");
    }
    for (size_t i = 0; i < f.size(); ++i)
    {
      const std::string key = At("volume.files", i);
      s.Files.push_back(ResolvePath(String(f[i], key), baseDir, key));
    }
  }
  else
  {
    Fail("volume.file", "missing required key (or 'files' for a .vdb sequence)");
  }
  if (v.Read("grid", s.Grid) && s.Grid.empty())
  {
    Fail("volume.grid", "empty grid name");
  }
  if (v.Has("time_step"))
  {
    if (s.Files.empty())
    {
      Fail("volume.time_step", "only for a sequence ('files')");
    }
    s.TimeStep = v.Integer("time_step", 0, static_cast<long long>(s.Files.size()) - 1);
  }
  return s;
}

Scene::TransferFunctionSection ParseTransferFunction(const json& value)
{
  const SceneSection v(value, "transfer_function");
  Scene::TransferFunctionSection s;
  s.Opacity = Points<2>(v, "opacity", "[scalar, opacity]", "scalar", "scalar");
  if (v.Has("color"))
  {
    s.Color = Points<4>(v, "color", "[scalar, r, g, b]", "scalar", "scalar");
  }
  v.Read("unit_distance", s.UnitDistance);
  v.Read("density_scale", s.DensityScale);
  if (v.Has("interpolation"))
  {
    s.Nearest = v.String("interpolation") == "nearest";
  }
  if (v.Has("gradient_opacity"))
  {
    s.GradientOpacity = Points<2>(
      v, "gradient_opacity", "[gradient magnitude, opacity]", "gradient magnitude", "magnitude", "a gradient magnitude");
  }
  // issue 38: the property's shading.
  v.Read("shade", s.Shade);
  v.Read("ambient", s.Ambient);
  v.Read("diffuse", s.Diffuse);
  v.Read("specular", s.Specular);
  v.Read("specular_power", s.SpecularPower);
  return s;
}

Scene::EnvironmentSection ParseEnvironment(const json& value, const std::string& baseDir)
{
  const std::string path = "environment";
  const SceneSection v(value, path);
  Scene::EnvironmentSection s;
  const int sources = int(v.Has("file")) + int(v.Has("constant")) + int(v.Has("sun")) + int(v.Has("two_tone"));
  if (sources == 0)
  {
    Fail(path, "missing a source: 'file', or one of 'constant', 'sun', 'two_tone'");
  }
  if (sources > 1)
  {
    Fail(path, "give only one of 'file', 'constant', 'sun', 'two_tone'");
  }
  using Kind = Scene::EnvironmentSection::Kind;
  if (v.Has("file"))
  {
    s.Type = Kind::File;
    s.File = v.File("file", baseDir);
  }
  else if (v.Has("constant"))
  {
    s.Type = Kind::Constant;
    s.Constant = v.Vector("constant");
  }
  else if (v.Has("sun"))
  {
    s.Type = Kind::Sun;
    const SceneSection sun(v["sun"], "environment.sun");
    s.SunDirection = sun.Vector("direction");
    sun.Read("radius_deg", s.SunRadiusDeg);
    sun.Read("radiance", s.SunRadiance);
    sun.Read("sky", s.SunSky);
  }
  else
  {
    s.Type = Kind::TwoTone;
    const SceneSection t(v["two_tone"], "environment.two_tone");
    s.Upper = t.Vector("upper");
    s.Lower = t.Vector("lower");
  }
  if (v.Has("octahedral_size"))
  {
    // 0 (automatic) only for a file: a procedural environment has no size of its own.
    s.OctahedralSize =
      v.Integer("octahedral_size", s.Type == Kind::File ? 0 : 1, static_cast<long long>(v.Entry("octahedral_size").Max));
    if (s.OctahedralSize != 0 && !IsPowerOfTwo(s.OctahedralSize))
    {
      Fail("environment.octahedral_size", "size " + std::to_string(s.OctahedralSize) + " is not a power of two");
    }
  }
  if (v.Has("rotation_deg"))
  {
    if (s.Type != Kind::File)
    {
      Fail("environment.rotation_deg", "only for an environment 'file' (set the procedural directions instead)");
    }
    s.RotationDeg = v.Number("rotation_deg");
  }
  v.Read("intensity", s.Intensity);
  v.Read("visible_background", s.VisibleBackground);
  v.Read("background", s.Background);
  return s;
}

Scene::CameraSection ParseCamera(const json& value)
{
  const SceneSection v(value, "camera");
  Scene::CameraSection s;
  s.Position = v.Vector("position");
  s.FocalPoint = v.Vector("focal_point");
  s.ViewUp = Vec3{ 0, 0, 1 };
  v.Read("view_up", s.ViewUp);
  v.Read("view_angle", s.ViewAngle);
  v.Read("parallel_scale", s.ParallelScale);
  const Vec3 d{ s.FocalPoint[0] - s.Position[0], s.FocalPoint[1] - s.Position[1], s.FocalPoint[2] - s.Position[2] };
  const double dn = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (dn == 0.0)
  {
    Fail("camera.focal_point", "the focal point equals the position");
  }
  // The view up normalised in double first: (1e300, 0, 0) and (1e-300, 0, 0) are directions too.
  const Vec3 u = Normalized(s.ViewUp);
  const Vec3 c{ d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0] };
  if (std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) < 1e-6 * dn)
  {
    Fail("camera.view_up", "parallel to the view direction");
  }
  return s;
}

Scene::RenderSection ParseRender(const json& value)
{
  const SceneSection v(value, "render");
  Scene::RenderSection s;
  v.Read("width", s.Width);
  v.Read("height", s.Height);
  v.Read("spp", s.Spp);
  v.Read("strategy", s.Strategy);
  v.Read("seed", s.Seed);
  v.Read("exposure", s.Exposure);
  v.Read("tone_mapping", s.ToneMapping);
  v.Read("update_scheme", s.UpdateScheme);
  v.Read("directions_per_frame", s.DirectionsPerFrame);
  v.Read("static_interval", s.StaticInterval);
  v.Read("shadow_rays", s.ShadowRays);
  v.Read("max_scattering_events", s.MaxScatteringEvents);
  v.Read("anisotropy", s.Anisotropy);
  v.Read("volumetric_scattering_blending", s.VolumetricScatteringBlending); // issue 38
  v.Read("control_extinction", s.ControlExtinction);
  v.Read("transmittance_estimator", s.TransmittanceEstimator);
  v.Read("sampler", s.Sampler);
  v.Read("mode", s.Mode);
  return s;
}

Scene::VisibilitySection ParseVisibility(const json& value)
{
  const SceneSection v(value, "visibility");
  Scene::VisibilitySection s;
  if (v.Read("direction_resolution", s.DirectionResolution))
  {
    const int r = *s.DirectionResolution;
    if (r != 4 && r != 8 && r != 16)
    {
      Fail("visibility.direction_resolution", "resolution " + std::to_string(r) + " is not 4, 8 or 16");
    }
  }
  v.Read("voxels_per_cell", s.VoxelsPerCell);
  v.Read("kernel_resolution", s.KernelResolution);
  v.Read("filtering", s.Filtering);
  v.Read("extinction_pooling", s.ExtinctionPooling);
  v.Read("skip_unlit_directions", s.SkipUnlitDirections);
  v.Read("light_weighted_directions", s.LightWeightedDirections);
  v.Read("fill_unswept", s.FillUnswept);
  v.Read("progressive", s.Progressive);
  v.Read("sweep_frame_fraction", s.SweepFrameFraction);
  v.Read("filter_angle_fraction", s.FilterAngleFraction);
  v.Read("epsilon", s.Epsilon);
  v.Read("cell_mode", s.CellMode);
  return s;
}

std::vector<Scene::ClipPlane> ParseClipPlanes(const json& v)
{
  if (!v.is_array())
  {
    Fail("clip_planes", std::string("expected an array of {\"origin\", \"normal\"} objects, got ") + v.type_name());
  }
  std::vector<Scene::ClipPlane> planes;
  for (size_t i = 0; i < v.size(); ++i)
  {
    const SceneSection plane(v[i], "clip_planes[]", At("clip_planes", i));
    Scene::ClipPlane p;
    p.Origin = plane.Vector("origin");
    p.Normal = plane.Vector("normal");
    planes.push_back(p);
  }
  return planes;
}

// issue 38: VTK's lights, each checked by the schema's "lights[]" entries and by what its type allows.
std::vector<Scene::Light> ParseLights(const json& v)
{
  if (!v.is_array())
  {
    Fail("lights", std::string("expected an array of light objects ({\"type\", \"position\", ...}), got ") +
        v.type_name());
  }
  std::vector<Scene::Light> lights;
  for (size_t i = 0; i < v.size(); ++i)
  {
    const SceneSection light(v[i], "lights[]", At("lights", i));
    Scene::Light l;
    light.Read("type", l.Type);
    const bool positional = l.Type != "directional", spot = l.Type == "spot";
    for (const char* key : { "cone_angle", "exponent" })
    {
      if (!spot && light.Has(key))
      {
        Fail(light.Key(key), "only for a spot light (\"type\": \"spot\"), not a " + l.Type + " one");
      }
    }
    if (!positional && light.Has("attenuation"))
    {
      Fail(light.Key("attenuation"), "only for a positional or spot light (a directional light does not fall off)");
    }
    if (light.Has("direction") && light.Has("position"))
    {
      Fail(light.Key("direction"), "give either 'direction' or 'position', not both");
    }
    if (positional && light.Has("direction"))
    {
      Fail(light.Key("direction"), "only for a directional light (a " + l.Type + " light has a 'position')");
    }
    light.Read("position", l.Position);
    Vec3 direction{};
    if (light.Read("direction", direction))
    {
      l.Direction = direction;
    }
    light.Read("focal_point", l.FocalPoint);
    if (!l.Direction && l.Position == l.FocalPoint)
    {
      Fail(light.Key("position"), "the position is the focal point: the light has no direction");
    }
    light.Read("color", l.Color);
    light.Read("intensity", l.Intensity);
    light.Read("cone_angle", l.ConeAngle);
    light.Read("exponent", l.Exponent);
    light.Read("attenuation", l.Attenuation);
    if (l.Attenuation[0] == 0.0 && l.Attenuation[1] == 0.0 && l.Attenuation[2] == 0.0)
    {
      Fail(light.Key("attenuation"), "all three coefficients are 0: the light would be infinitely bright");
    }
    light.Read("follow_camera", l.FollowCamera);
    lights.push_back(l);
  }
  return lights;
}
}

Vec3 Normalized(const Vec3& d)
{
  const double m = std::max({ std::abs(d[0]), std::abs(d[1]), std::abs(d[2]) });
  if (!(m > 0.0) || !std::isfinite(m))
  {
    return d;
  }
  const Vec3 v{ d[0] / m, d[1] / m, d[2] / m }; // largest component 1: no square overflows
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return Vec3{ v[0] / length, v[1] / length, v[2] / length };
}

int StrategyIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneStrategies(), name, key, "strategy");
}

int ControlExtinctionIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneControlExtinctions(), name, key, "control extinction");
}

int TransmittanceEstimatorIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneTransmittanceEstimators(), name, key, "transmittance estimator");
}

int SamplerIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneSamplers(), name, key, "sampler");
}

int RenderModeIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneRenderModes(), name, key, "render mode");
}

int UpdateSchemeIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneUpdateSchemes(), name, key, "update scheme");
}

Scene ParseScene(const json& value, const std::string& baseDir)
{
  const SceneSection j(value, "");
  if (j.Has("description"))
  {
    j.String("description");
  }
  Scene s;
  s.Volume = ParseVolume(j["volume"], baseDir);
  s.TransferFunction = ParseTransferFunction(j["transfer_function"]);
  if (j.Has("environment"))
  {
    s.Environment = ParseEnvironment(j["environment"], baseDir);
  }
  if (j.Has("camera"))
  {
    s.Camera = ParseCamera(j["camera"]);
  }
  else
  {
    s.Camera.Reset = true;
    s.Camera.Position = { 0, -1, 0 }; // the direction; the renderer frames the volume along it
  }
  if (j.Has("render"))
  {
    s.Render = ParseRender(j["render"]);
  }
  if (j.Has("visibility"))
  {
    s.Visibility = ParseVisibility(j["visibility"]);
  }
  if (j.Has("clip_planes"))
  {
    s.ClipPlanes = ParseClipPlanes(j["clip_planes"]);
  }
  if (j.Has("lights"))
  {
    s.Lights = ParseLights(j["lights"]);
  }
  return s;
}

Scene ParseSceneText(const std::string& text, const std::string& baseDir)
{
  json j;
  try
  {
    j = json::parse(text);
  }
  catch (const json::exception& e)
  {
    // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    // Not only parse_error: a number beyond the range of a double ("1e999") is an
    // out_of_range.406 ("number overflow parsing '1e999'"), found by fuzzing.
    std::string what = e.what();
    const auto pos = what.find("] ");
    throw std::runtime_error("invalid JSON: " + (pos == std::string::npos ? what : what.substr(pos + 2)));
  }
  return ParseScene(j, baseDir);
}

Scene ReadSceneFile(const std::string& path)
{
  // A directory opened as a stream reads as empty ("invalid JSON ... unexpected end of input"),
  // and a FIFO or device would block: say what the path is instead.
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::is_directory(st))
  {
    throw std::runtime_error("scene file '" + path + "' is a directory, not a JSON scene file");
  }
  if (!ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st))
  {
    throw std::runtime_error("scene file '" + path + "' is not a regular file (a FIFO, device or socket)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot open scene file '" + path + "'");
  }
  std::stringstream text;
  text << in.rdbuf();
  std::string base = std::filesystem::absolute(std::filesystem::path(path)).parent_path().string();
  try
  {
    return ParseSceneText(text.str(), base);
  }
  catch (const std::runtime_error& e)
  {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}
