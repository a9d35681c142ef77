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
Scene::VolumeSection ParseVolume(const json& v, const std::string& baseDir)
{
  const std::string path = "volume";
  RequireObject(v, path);
  CheckKeys(v, path, { "file", "files", "grid", "time_step" });
  Scene::VolumeSection s;
  if (v.contains("file") && v.contains("files"))
  {
    Fail(path, "give either 'file' or 'files', not both");
  }
  if (v.contains("file"))
  {
    s.File = ResolvePath(String(v["file"], "volume.file"), baseDir, "volume.file");
  }
  else if (v.contains("files"))
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
  if (v.contains("grid"))
  {
    s.Grid = String(v["grid"], "volume.grid");
    if (s.Grid.empty())
    {
      Fail("volume.grid", "empty grid name");
    }
  }
  if (v.contains("time_step"))
  {
    if (s.Files.empty())
    {
      Fail("volume.time_step", "only for a sequence ('files')");
    }
    s.TimeStep = Integer(v["time_step"], "volume.time_step", 0, static_cast<long long>(s.Files.size()) - 1,
      "time step");
  }
  return s;
}

Scene::TransferFunctionSection ParseTransferFunction(const json& v)
{
  const std::string path = "transfer_function";
  RequireObject(v, path);
  CheckKeys(v, path, { "opacity", "color", "unit_distance", "density_scale", "interpolation", "gradient_opacity" });
  Scene::TransferFunctionSection s;
  const json& op = Require(v, path, "opacity");
  if (!op.is_array() || op.empty())
  {
    Fail("transfer_function.opacity", "expected a non-empty array of [scalar, opacity] points");
  }
  for (size_t i = 0; i < op.size(); ++i)
  {
    const std::string key = At("transfer_function.opacity", i);
    auto p = Numbers<2>(op[i], key);
    FitsFloat(p[0], At(key, 0));
    NumberIn(op[i][1], At(key, 1), 0.0, 1.0, "opacity");
    if (!s.Opacity.empty() && !(p[0] > s.Opacity.back()[0]))
    {
      Fail(At(key, 0), "scalar " + Num(p[0]) + " does not follow " + Num(s.Opacity.back()[0]) +
          " (points must be sorted by increasing scalar)");
    }
    s.Opacity.push_back(p);
  }
  if (v.contains("color"))
  {
    const json& c = v["color"];
    if (!c.is_array() || c.empty())
    {
      Fail("transfer_function.color", "expected a non-empty array of [scalar, r, g, b] points");
    }
    for (size_t i = 0; i < c.size(); ++i)
    {
      const std::string key = At("transfer_function.color", i);
      auto p = Numbers<4>(c[i], key);
      FitsFloat(p[0], At(key, 0));
      for (size_t k = 1; k < 4; ++k)
      {
        NumberIn(c[i][k], At(key, k), 0.0, 1.0, "albedo");
      }
      if (!s.Color.empty() && !(p[0] > s.Color.back()[0]))
      {
        Fail(At(key, 0), "scalar " + Num(p[0]) + " does not follow " + Num(s.Color.back()[0]) +
            " (points must be sorted by increasing scalar)");
      }
      s.Color.push_back(p);
    }
  }
  if (v.contains("unit_distance"))
  {
    s.UnitDistance = PositiveFloat(v["unit_distance"], "transfer_function.unit_distance", "the unit distance");
  }
  if (v.contains("density_scale"))
  {
    s.DensityScale = FitsFloat(
      NonNegative(v["density_scale"], "transfer_function.density_scale", "the density scale"),
      "transfer_function.density_scale");
  }
  if (v.contains("interpolation"))
  {
    const std::string m = String(v["interpolation"], "transfer_function.interpolation");
    if (m != "linear" && m != "nearest")
    {
      Fail("transfer_function.interpolation", "unknown interpolation '" + m + "' (expected linear, nearest)");
    }
    s.Nearest = m == "nearest";
  }
  if (v.contains("gradient_opacity"))
  {
    const json& g = v["gradient_opacity"];
    if (!g.is_array() || g.empty())
    {
      Fail("transfer_function.gradient_opacity", "expected a non-empty array of [gradient magnitude, opacity] points");
    }
    for (size_t i = 0; i < g.size(); ++i)
    {
      const std::string key = At("transfer_function.gradient_opacity", i);
      auto p = Numbers<2>(g[i], key);
      FitsFloat(NonNegative(g[i][0], At(key, 0), "a gradient magnitude"), At(key, 0));
      NumberIn(g[i][1], At(key, 1), 0.0, 1.0, "opacity");
      if (!s.GradientOpacity.empty() && !(p[0] > s.GradientOpacity.back()[0]))
      {
        Fail(At(key, 0), "gradient magnitude " + Num(p[0]) + " does not follow " + Num(s.GradientOpacity.back()[0]) +
            " (points must be sorted by increasing magnitude)");
      }
      s.GradientOpacity.push_back(p);
    }
  }
  return s;
}

Scene::EnvironmentSection ParseEnvironment(const json& v, const std::string& baseDir)
{
  const std::string path = "environment";
  RequireObject(v, path);
  CheckKeys(v, path,
    { "file", "constant", "sun", "two_tone", "octahedral_size", "rotation_deg", "intensity", "visible_background",
      "background" });
  Scene::EnvironmentSection s;
  const int sources = int(v.contains("file")) + int(v.contains("constant")) + int(v.contains("sun")) +
    int(v.contains("two_tone"));
  if (sources == 0)
  {
    Fail(path, "missing a source: 'file', or one of 'constant', 'sun', 'two_tone'");
  }
  if (sources > 1)
  {
    Fail(path, "give only one of 'file', 'constant', 'sun', 'two_tone'");
  }
  if (v.contains("file"))
  {
    s.Type = Scene::EnvironmentSection::Kind::File;
    s.File = ResolvePath(String(v["file"], "environment.file"), baseDir, "environment.file");
  }
  else if (v.contains("constant"))
  {
    s.Type = Scene::EnvironmentSection::Kind::Constant;
    s.Constant = Color3(v["constant"], "environment.constant", "radiance");
  }
  else if (v.contains("sun"))
  {
    s.Type = Scene::EnvironmentSection::Kind::Sun;
    const json& sun = v["sun"];
    RequireObject(sun, "environment.sun");
    CheckKeys(sun, "environment.sun", { "direction", "radius_deg", "radiance", "sky" });
    s.SunDirection = Direction(Require(sun, "environment.sun", "direction"), "environment.sun.direction");
    if (sun.contains("radius_deg"))
    {
      s.SunRadiusDeg = NumberIn(sun["radius_deg"], "environment.sun.radius_deg", 0.0, 180.0, "radius");
    }
    if (sun.contains("radiance"))
    {
      s.SunRadiance = Color3(sun["radiance"], "environment.sun.radiance", "radiance");
    }
    if (sun.contains("sky"))
    {
      s.SunSky = Color3(sun["sky"], "environment.sun.sky", "radiance");
    }
  }
  else
  {
    s.Type = Scene::EnvironmentSection::Kind::TwoTone;
    const json& t = v["two_tone"];
    RequireObject(t, "environment.two_tone");
    CheckKeys(t, "environment.two_tone", { "upper", "lower" });
    s.Upper = Color3(Require(t, "environment.two_tone", "upper"), "environment.two_tone.upper", "radiance");
    s.Lower = Color3(Require(t, "environment.two_tone", "lower"), "environment.two_tone.lower", "radiance");
  }
  if (v.contains("octahedral_size"))
  {
    const bool file = s.Type == Scene::EnvironmentSection::Kind::File;
    s.OctahedralSize = Integer(v["octahedral_size"], "environment.octahedral_size", file ? 0 : 1, 32768, "size");
    if (s.OctahedralSize != 0 && !IsPowerOfTwo(s.OctahedralSize))
    {
      Fail("environment.octahedral_size", "size " + std::to_string(s.OctahedralSize) + " is not a power of two");
    }
  }
  if (v.contains("rotation_deg"))
  {
    if (s.Type != Scene::EnvironmentSection::Kind::File)
    {
      Fail("environment.rotation_deg", "only for an environment 'file' (set the procedural directions instead)");
    }
    s.RotationDeg = Number(v["rotation_deg"], "environment.rotation_deg");
  }
  if (v.contains("intensity"))
  {
    s.Intensity = FitsFloat(NonNegative(v["intensity"], "environment.intensity", "the intensity"), "environment.intensity");
  }
  if (v.contains("visible_background"))
  {
    s.VisibleBackground = Boolean(v["visible_background"], "environment.visible_background");
  }
  if (v.contains("background"))
  {
    s.Background = Color3(v["background"], "environment.background", "colour");
  }
  return s;
}

Scene::CameraSection ParseCamera(const json& v)
{
  const std::string path = "camera";
  RequireObject(v, path);
  CheckKeys(v, path, { "position", "focal_point", "view_up", "view_angle", "parallel_scale" });
  Scene::CameraSection s;
  s.Position = Point3(Require(v, path, "position"), "camera.position");
  s.FocalPoint = Point3(Require(v, path, "focal_point"), "camera.focal_point");
  s.ViewUp = Vec3{ 0, 0, 1 };
  if (v.contains("view_up"))
  {
    s.ViewUp = Direction(v["view_up"], "camera.view_up");
  }
  if (v.contains("view_angle"))
  {
    s.ViewAngle = Number(v["view_angle"], "camera.view_angle");
    if (!(s.ViewAngle > 0.0 && s.ViewAngle < 180.0))
    {
      Fail("camera.view_angle", "angle " + Num(s.ViewAngle) + " not in (0, 180) degrees");
    }
  }
  if (v.contains("parallel_scale"))
  {
    s.ParallelScale = PositiveFloat(v["parallel_scale"], "camera.parallel_scale", "the parallel scale");
  }
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

Scene::RenderSection ParseRender(const json& v)
{
  const std::string path = "render";
  RequireObject(v, path);
  CheckKeys(v, path,
    { "width", "height", "spp", "strategy", "seed", "exposure", "tone_mapping", "update_scheme",
      "directions_per_frame", "static_interval", "control_extinction", "transmittance_estimator", "sampler", "shadow_rays" });
  Scene::RenderSection s;
  if (v.contains("width"))
  {
    s.Width = Integer(v["width"], "render.width", 1, 16384, "width");
  }
  if (v.contains("height"))
  {
    s.Height = Integer(v["height"], "render.height", 1, 16384, "height");
  }
  if (v.contains("spp"))
  {
    s.Spp = Integer(v["spp"], "render.spp", 1, 1 << 30, "samples per pixel");
  }
  if (v.contains("strategy"))
  {
    s.Strategy = SceneStrategies()[StrategyIndex(String(v["strategy"], "render.strategy"), "render.strategy")];
  }
  if (v.contains("seed"))
  {
    s.Seed = Integer(v["seed"], "render.seed", 0, std::numeric_limits<int>::max(), "seed");
  }
  if (v.contains("exposure"))
  {
    s.Exposure = FitsFloat(NonNegative(v["exposure"], "render.exposure", "the exposure"), "render.exposure");
  }
  if (v.contains("tone_mapping"))
  {
    s.ToneMapping = Boolean(v["tone_mapping"], "render.tone_mapping");
  }
  if (v.contains("update_scheme"))
  {
    s.UpdateScheme = String(v["update_scheme"], "render.update_scheme");
    UpdateSchemeIndex(s.UpdateScheme, "render.update_scheme");
  }
  if (v.contains("directions_per_frame"))
  {
    s.DirectionsPerFrame =
      Integer(v["directions_per_frame"], "render.directions_per_frame", 1, 4096, "directions per frame");
  }
  if (v.contains("static_interval"))
  {
    s.StaticInterval = Integer(v["static_interval"], "render.static_interval", 1,
      std::numeric_limits<int>::max(), "frames between static updates");
  }
  if (v.contains("shadow_rays"))
  {
    s.ShadowRays = Integer(v["shadow_rays"], "render.shadow_rays", 1, 64, "shadow rays per scatter point");
  }
  if (v.contains("control_extinction"))
  {
    s.ControlExtinction = String(v["control_extinction"], "render.control_extinction");
    ControlExtinctionIndex(s.ControlExtinction, "render.control_extinction");
  }
  if (v.contains("transmittance_estimator"))
  {
    s.TransmittanceEstimator = String(v["transmittance_estimator"], "render.transmittance_estimator");
    TransmittanceEstimatorIndex(s.TransmittanceEstimator, "render.transmittance_estimator");
  }
  if (v.contains("sampler"))
  {
    s.Sampler = String(v["sampler"], "render.sampler");
    SamplerIndex(s.Sampler, "render.sampler");
  }
  return s;
}

Scene::VisibilitySection ParseVisibility(const json& v)
{
  const std::string path = "visibility";
  RequireObject(v, path);
  CheckKeys(v, path,
    { "direction_resolution", "voxels_per_cell", "kernel_resolution", "filtering", "filter_angle_fraction", "epsilon",
      "cell_mode", "skip_unlit_directions", "progressive", "sweep_frame_fraction",
      "light_weighted_directions", "fill_unswept", "extinction_pooling" });
  Scene::VisibilitySection s;
  if (v.contains("direction_resolution"))
  {
    const int r = Integer(v["direction_resolution"], "visibility.direction_resolution", 1, 1024, "resolution");
    if (r != 4 && r != 8 && r != 16)
    {
      Fail("visibility.direction_resolution", "resolution " + std::to_string(r) + " is not 4, 8 or 16");
    }
    s.DirectionResolution = r;
  }
  if (v.contains("voxels_per_cell"))
  {
    s.VoxelsPerCell = Positive(v["voxels_per_cell"], "visibility.voxels_per_cell", "voxels per cell");
  }
  if (v.contains("kernel_resolution"))
  {
    s.KernelResolution = Integer(v["kernel_resolution"], "visibility.kernel_resolution", 0, 1 << 14, "rays");
  }
  if (v.contains("filtering"))
  {
    s.Filtering = Boolean(v["filtering"], "visibility.filtering");
  }
  if (v.contains("extinction_pooling"))
  {
    s.ExtinctionPooling = Integer(v["extinction_pooling"], "visibility.extinction_pooling", 0, 16, "voxels per texel");
  }
  if (v.contains("skip_unlit_directions"))
  {
    s.SkipUnlitDirections = Boolean(v["skip_unlit_directions"], "visibility.skip_unlit_directions");
  }
  if (v.contains("light_weighted_directions"))
  {
    s.LightWeightedDirections = Boolean(v["light_weighted_directions"], "visibility.light_weighted_directions");
  }
  if (v.contains("fill_unswept"))
  {
    s.FillUnswept = Boolean(v["fill_unswept"], "visibility.fill_unswept");
  }
  if (v.contains("progressive"))
  {
    s.Progressive = Boolean(v["progressive"], "visibility.progressive");
  }
  if (v.contains("sweep_frame_fraction"))
  {
    s.SweepFrameFraction = NumberIn(v["sweep_frame_fraction"], "visibility.sweep_frame_fraction", 0.0, 1000.0, "fraction");
  }
  if (v.contains("filter_angle_fraction"))
  {
    s.FilterAngleFraction = NumberIn(v["filter_angle_fraction"], "visibility.filter_angle_fraction", 0.0, 1.0, "fraction");
  }
  if (v.contains("epsilon"))
  {
    const double e = Number(v["epsilon"], "visibility.epsilon");
    if (!(e > 0.0 && e <= 1.0))
    {
      Fail("visibility.epsilon", "epsilon " + Num(e) + " not in (0, 1]");
    }
    s.Epsilon = e;
  }
  if (v.contains("cell_mode"))
  {
    const std::string m = String(v["cell_mode"], "visibility.cell_mode");
    if (m != "trilinear" && m != "stochastic")
    {
      Fail("visibility.cell_mode", "unknown cell mode '" + m + "' (expected trilinear, stochastic)");
    }
    s.CellMode = m;
  }
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
    const std::string key = At("clip_planes", i);
    RequireObject(v[i], key);
    CheckKeys(v[i], key, { "origin", "normal" });
    Scene::ClipPlane p;
    p.Origin = Point3(Require(v[i], key, "origin"), key + ".origin");
    p.Normal = Direction(Require(v[i], key, "normal"), key + ".normal");
    planes.push_back(p);
  }
  return planes;
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

const std::vector<std::string>& SceneStrategies()
{
  static const std::vector<std::string> names{ "uniform", "environment", "visibility", "combined", "two-step", "auto" };
  return names;
}

namespace
{
// "Two-Step", "two_step", "TwoStep" -> "twostep".
std::string Folded(const std::string& name)
{
  std::string f;
  for (const char c : name)
  {
    if (c != '-' && c != '_')
    {
      f += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  return f;
}
}

int StrategyIndex(const std::string& name, const std::string& key)
{
  const auto& names = SceneStrategies();
  auto it = std::find_if(
    names.begin(), names.end(), [&](const std::string& n) { return Folded(n) == Folded(name); });
  if (it == names.end())
  {
    Fail(key, "unknown strategy '" + name + "' (expected " + List(names) + ")");
  }
  return static_cast<int>(it - names.begin());
}

const std::vector<std::string>& SceneUpdateSchemes()
{
  static const std::vector<std::string> names{ "full", "round-robin", "environment-guided", "static" };
  return names;
}

const std::vector<std::string>& SceneControlExtinctions()
{
  static const std::vector<std::string> names{ "none", "shadow", "camera", "both" };
  return names;
}

int ControlExtinctionIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneControlExtinctions(), name, key, "control extinction");
}

const std::vector<std::string>& SceneTransmittanceEstimators()
{
  static const std::vector<std::string> names{ "ratio-tracking", "ray-marching" };
  return names;
}

int TransmittanceEstimatorIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneTransmittanceEstimators(), name, key, "transmittance estimator");
}

const std::vector<std::string>& SceneSamplers()
{
  static const std::vector<std::string> names{ "independent", "sobol" };
  return names;
}

int SamplerIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneSamplers(), name, key, "sampler");
}

int UpdateSchemeIndex(const std::string& name, const std::string& key)
{
  return NameIndex(SceneUpdateSchemes(), name, key, "update scheme");
}

Scene ParseScene(const json& j, const std::string& baseDir)
{
  RequireObject(j, "");
  CheckKeys(j, "",
    { "description", "volume", "transfer_function", "environment", "camera", "render", "visibility", "clip_planes" });
  if (j.contains("description"))
  {
    String(j["description"], "description");
  }
  Scene s;
  s.Volume = ParseVolume(Require(j, "", "volume"), baseDir);
  s.TransferFunction = ParseTransferFunction(Require(j, "", "transfer_function"));
  if (j.contains("environment"))
  {
    s.Environment = ParseEnvironment(j["environment"], baseDir);
  }
  if (j.contains("camera"))
  {
    s.Camera = ParseCamera(j["camera"]);
  }
  else
  {
    s.Camera.Reset = true;
    s.Camera.Position = { 0, -1, 0 }; // the direction; the renderer frames the volume along it
  }
  if (j.contains("render"))
  {
    s.Render = ParseRender(j["render"]);
  }
  if (j.contains("visibility"))
  {
    s.Visibility = ParseVisibility(j["visibility"]);
  }
  if (j.contains("clip_planes"))
  {
    s.ClipPlanes = ParseClipPlanes(j["clip_planes"]);
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
