#include "vsSceneFile.h"

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

namespace
{
[[noreturn]] void Fail(const std::string& key, const std::string& message)
{
  throw std::runtime_error((key.empty() ? std::string("scene") : key) + ": " + message);
}

std::string Join(const std::string& path, const std::string& key)
{
  return path.empty() ? key : path + "." + key;
}

std::string At(const std::string& path, size_t i)
{
  return path + "[" + std::to_string(i) + "]";
}

std::string Num(double v)
{
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string List(const std::vector<std::string>& names)
{
  std::string s;
  for (size_t i = 0; i < names.size(); ++i)
  {
    s += (i ? ", " : "") + names[i];
  }
  return s;
}

void RequireObject(const json& v, const std::string& key)
{
  if (!v.is_object())
  {
    Fail(key, std::string("expected an object, got ") + v.type_name());
  }
}

void CheckKeys(const json& obj, const std::string& path, const std::vector<std::string>& allowed)
{
  for (auto it = obj.begin(); it != obj.end(); ++it)
  {
    if (std::find(allowed.begin(), allowed.end(), it.key()) == allowed.end())
    {
      Fail(Join(path, it.key()), "unknown key (expected " + List(allowed) + ")");
    }
  }
}

const json& Require(const json& obj, const std::string& path, const std::string& key)
{
  if (!obj.contains(key))
  {
    Fail(Join(path, key), "missing required key");
  }
  return obj.at(key);
}

double Number(const json& v, const std::string& key)
{
  if (!v.is_number())
  {
    Fail(key, std::string("expected a number, got ") + v.type_name());
  }
  const double d = v.get<double>();
  if (!std::isfinite(d))
  {
    Fail(key, "expected a finite number");
  }
  return d;
}

// The renderer computes in float: a finite double beyond float's range became an infinity or a
// zero on the device (issue 13, item 5), so such values are refused naming the key and the limit.
constexpr double kFloatMax = double(std::numeric_limits<float>::max());
constexpr double kFloatMinNormal = double(std::numeric_limits<float>::min());

double FitsFloat(double d, const std::string& key)
{
  if (!(std::abs(d) <= kFloatMax))
  {
    Fail(key, Num(d) + " is outside the range of float, which the renderer computes in (magnitude at most " +
        Num(kFloatMax) + ")");
  }
  return d;
}

double FloatNumber(const json& v, const std::string& key)
{
  return FitsFloat(Number(v, key), key);
}

// A positive length or scale whose float must be neither zero, denormal nor infinite.
double PositiveFloat(const json& v, const std::string& key, const std::string& what)
{
  const double d = Number(v, key);
  if (!(d > 0.0))
  {
    Fail(key, what + " must be positive, got " + Num(d));
  }
  if (!(d >= kFloatMinNormal && d <= kFloatMax))
  {
    Fail(key, what + " " + Num(d) + " is outside the range of float, which the renderer computes in (between " +
        Num(kFloatMinNormal) + " and " + Num(kFloatMax) + ")");
  }
  return d;
}

double NumberIn(const json& v, const std::string& key, double lo, double hi, const std::string& what)
{
  const double d = Number(v, key);
  if (d < lo || d > hi)
  {
    Fail(key, what + " " + Num(d) + " not in [" + Num(lo) + ", " + Num(hi) + "]");
  }
  return d;
}

double Positive(const json& v, const std::string& key, const std::string& what)
{
  const double d = Number(v, key);
  if (!(d > 0.0))
  {
    Fail(key, what + " must be positive, got " + Num(d));
  }
  return d;
}

double NonNegative(const json& v, const std::string& key, const std::string& what)
{
  const double d = Number(v, key);
  if (d < 0.0)
  {
    Fail(key, what + " must not be negative, got " + Num(d));
  }
  return d;
}

int Integer(const json& v, const std::string& key, long long lo, long long hi, const std::string& what)
{
  if (!v.is_number())
  {
    Fail(key, std::string("expected an integer, got ") + v.type_name());
  }
  long long i = 0;
  if (v.is_number_integer())
  {
    i = v.is_number_unsigned() ? static_cast<long long>(std::min<unsigned long long>(v.get<unsigned long long>(),
                                   static_cast<unsigned long long>(std::numeric_limits<long long>::max())))
                               : v.get<long long>();
  }
  else
  {
    const double d = v.get<double>();
    if (!std::isfinite(d) || d != std::floor(d) || std::abs(d) > 9e15)
    {
      Fail(key, "expected an integer, got " + Num(d));
    }
    i = static_cast<long long>(d);
  }
  if (i < lo || i > hi)
  {
    Fail(key, what + " " + std::to_string(i) + " not in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return static_cast<int>(i);
}

bool Boolean(const json& v, const std::string& key)
{
  if (!v.is_boolean())
  {
    Fail(key, std::string("expected true or false, got ") + v.type_name());
  }
  return v.get<bool>();
}

std::string String(const json& v, const std::string& key)
{
  if (!v.is_string())
  {
    Fail(key, std::string("expected a string, got ") + v.type_name());
  }
  return v.get<std::string>();
}

template <size_t N>
std::array<double, N> Numbers(const json& v, const std::string& key)
{
  if (!v.is_array() || v.size() != N)
  {
    Fail(key, "expected an array of " + std::to_string(N) + " numbers, got " +
        (v.is_array() ? std::to_string(v.size()) + " elements" : std::string(v.type_name())));
  }
  std::array<double, N> a{};
  for (size_t i = 0; i < N; ++i)
  {
    a[i] = Number(v[i], At(key, i));
  }
  return a;
}

Vec3 Color3(const json& v, const std::string& key, const std::string& what)
{
  Vec3 c = Numbers<3>(v, key);
  for (size_t i = 0; i < 3; ++i)
  {
    if (c[i] < 0.0)
    {
      Fail(At(key, i), what + " must not be negative, got " + Num(c[i]));
    }
    FitsFloat(c[i], At(key, i));
  }
  return c;
}

// A point: every component within float's range.
Vec3 Point3(const json& v, const std::string& key)
{
  Vec3 p = Numbers<3>(v, key);
  for (size_t i = 0; i < 3; ++i)
  {
    FitsFloat(p[i], At(key, i));
  }
  return p;
}

Vec3 Direction(const json& v, const std::string& key)
{
  Vec3 d = Numbers<3>(v, key);
  if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
  {
    Fail(key, "the direction must not be zero");
  }
  return d;
}

std::string ResolvePath(const std::string& file, const std::string& baseDir, const std::string& key)
{
  if (file.empty())
  {
    Fail(key, "empty file name");
  }
  std::filesystem::path p(file);
  if (p.is_relative() && !baseDir.empty())
  {
    p = std::filesystem::path(baseDir) / p;
  }
  return p.lexically_normal().string();
}

bool IsPowerOfTwo(int v)
{
  return v > 0 && (v & (v - 1)) == 0;
}

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

json Array3(const Vec3& v)
{
  return json::array({ v[0], v[1], v[2] });
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

namespace
{
// The index of `name` among a key's allowed words; an error naming the key, the word and the
// allowed ones otherwise.
int NameIndex(const std::vector<std::string>& names, const std::string& name, const std::string& key,
  const std::string& what)
{
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
  {
    Fail(key, "unknown " + what + " '" + name + "' (expected " + List(names) + ")");
  }
  return static_cast<int>(it - names.begin());
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

bool Scene::VolumeSection::operator==(const VolumeSection& o) const
{
  return std::tie(File, Files, Grid, TimeStep) == std::tie(o.File, o.Files, o.Grid, o.TimeStep);
}

bool Scene::TransferFunctionSection::operator==(const TransferFunctionSection& o) const
{
  return std::tie(Opacity, Color, UnitDistance, DensityScale, Nearest, GradientOpacity) ==
    std::tie(o.Opacity, o.Color, o.UnitDistance, o.DensityScale, o.Nearest, o.GradientOpacity);
}

bool Scene::EnvironmentSection::operator==(const EnvironmentSection& o) const
{
  if (std::tie(Type, OctahedralSize, Intensity, VisibleBackground, Background) !=
    std::tie(o.Type, o.OctahedralSize, o.Intensity, o.VisibleBackground, o.Background))
  {
    return false;
  }
  switch (Type)
  {
    case Kind::File:
      return File == o.File && RotationDeg == o.RotationDeg;
    case Kind::Constant:
      return Constant == o.Constant;
    case Kind::Sun:
      return std::tie(SunDirection, SunRadiusDeg, SunRadiance, SunSky) ==
        std::tie(o.SunDirection, o.SunRadiusDeg, o.SunRadiance, o.SunSky);
    case Kind::TwoTone:
      return Upper == o.Upper && Lower == o.Lower;
  }
  return false;
}

bool Scene::CameraSection::operator==(const CameraSection& o) const
{
  return std::tie(Position, FocalPoint, ViewUp, ViewAngle, ParallelScale, Reset) ==
    std::tie(o.Position, o.FocalPoint, o.ViewUp, o.ViewAngle, o.ParallelScale, o.Reset);
}

bool Scene::RenderSection::operator==(const RenderSection& o) const
{
  return std::tie(Width, Height, Spp, Strategy, Seed, Exposure, ToneMapping, UpdateScheme, DirectionsPerFrame,
           StaticInterval, ControlExtinction, TransmittanceEstimator, Sampler, ShadowRays) ==
    std::tie(o.Width, o.Height, o.Spp, o.Strategy, o.Seed, o.Exposure, o.ToneMapping, o.UpdateScheme,
      o.DirectionsPerFrame, o.StaticInterval, o.ControlExtinction, o.TransmittanceEstimator, o.Sampler,
      o.ShadowRays);
}

bool Scene::VisibilitySection::operator==(const VisibilitySection& o) const
{
  return std::tie(DirectionResolution, VoxelsPerCell, KernelResolution, Filtering, FilterAngleFraction, Epsilon,
           CellMode, SkipUnlitDirections, Progressive, SweepFrameFraction, LightWeightedDirections, FillUnswept,
           ExtinctionPooling) ==
    std::tie(o.DirectionResolution, o.VoxelsPerCell, o.KernelResolution, o.Filtering, o.FilterAngleFraction, o.Epsilon,
      o.CellMode, o.SkipUnlitDirections, o.Progressive, o.SweepFrameFraction, o.LightWeightedDirections,
      o.FillUnswept, o.ExtinctionPooling);
}

bool Scene::ClipPlane::operator==(const ClipPlane& o) const
{
  return Origin == o.Origin && Normal == o.Normal;
}

bool Scene::operator==(const Scene& o) const
{
  return Volume == o.Volume && TransferFunction == o.TransferFunction && Environment == o.Environment &&
    Camera == o.Camera && Render == o.Render && Visibility == o.Visibility && ClipPlanes == o.ClipPlanes;
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

json ToJson(const Scene& s)
{
  json j = json::object();
  json vol = json::object();
  if (!s.Volume.Files.empty())
  {
    vol["files"] = s.Volume.Files;
    vol["time_step"] = s.Volume.TimeStep;
  }
  else
  {
    vol["file"] = s.Volume.File;
  }
  vol["grid"] = s.Volume.Grid;
  j["volume"] = vol;

  json tf = json::object();
  tf["opacity"] = json::array();
  for (const auto& p : s.TransferFunction.Opacity)
  {
    tf["opacity"].push_back(json::array({ p[0], p[1] }));
  }
  if (!s.TransferFunction.Color.empty())
  {
    tf["color"] = json::array();
    for (const auto& p : s.TransferFunction.Color)
    {
      tf["color"].push_back(json::array({ p[0], p[1], p[2], p[3] }));
    }
  }
  tf["unit_distance"] = s.TransferFunction.UnitDistance;
  tf["density_scale"] = s.TransferFunction.DensityScale;
  tf["interpolation"] = s.TransferFunction.Nearest ? "nearest" : "linear";
  if (!s.TransferFunction.GradientOpacity.empty())
  {
    tf["gradient_opacity"] = json::array();
    for (const auto& p : s.TransferFunction.GradientOpacity)
    {
      tf["gradient_opacity"].push_back(json::array({ p[0], p[1] }));
    }
  }
  j["transfer_function"] = tf;

  const auto& e = s.Environment;
  json env = json::object();
  using Kind = Scene::EnvironmentSection::Kind;
  switch (e.Type)
  {
    case Kind::File:
      env["file"] = e.File;
      env["rotation_deg"] = e.RotationDeg;
      break;
    case Kind::Constant:
      env["constant"] = Array3(e.Constant);
      break;
    case Kind::Sun:
      env["sun"] = { { "direction", Array3(e.SunDirection) }, { "radius_deg", e.SunRadiusDeg },
        { "radiance", Array3(e.SunRadiance) }, { "sky", Array3(e.SunSky) } };
      break;
    case Kind::TwoTone:
      env["two_tone"] = { { "upper", Array3(e.Upper) }, { "lower", Array3(e.Lower) } };
      break;
  }
  if (e.OctahedralSize != 0)
  {
    env["octahedral_size"] = e.OctahedralSize;
  }
  env["intensity"] = e.Intensity;
  env["visible_background"] = e.VisibleBackground;
  env["background"] = Array3(e.Background);
  j["environment"] = env;

  if (!s.Camera.Reset)
  {
    json cam = json::object();
    cam["position"] = Array3(s.Camera.Position);
    cam["focal_point"] = Array3(s.Camera.FocalPoint);
    cam["view_up"] = Array3(s.Camera.ViewUp);
    cam["view_angle"] = s.Camera.ViewAngle;
    if (s.Camera.ParallelScale)
    {
      cam["parallel_scale"] = *s.Camera.ParallelScale;
    }
    j["camera"] = cam;
  }

  j["render"] = { { "width", s.Render.Width }, { "height", s.Render.Height }, { "spp", s.Render.Spp },
    { "strategy", s.Render.Strategy }, { "seed", s.Render.Seed }, { "exposure", s.Render.Exposure },
    { "tone_mapping", s.Render.ToneMapping }, { "update_scheme", s.Render.UpdateScheme },
    { "directions_per_frame", s.Render.DirectionsPerFrame }, { "static_interval", s.Render.StaticInterval },
    { "control_extinction", s.Render.ControlExtinction },
    { "transmittance_estimator", s.Render.TransmittanceEstimator }, { "sampler", s.Render.Sampler },
    { "shadow_rays", s.Render.ShadowRays } };

  const auto& v = s.Visibility;
  json vis = json::object();
  if (v.DirectionResolution)
    vis["direction_resolution"] = *v.DirectionResolution;
  if (v.VoxelsPerCell)
    vis["voxels_per_cell"] = *v.VoxelsPerCell;
  if (v.KernelResolution)
    vis["kernel_resolution"] = *v.KernelResolution;
  if (v.Filtering)
    vis["filtering"] = *v.Filtering;
  if (v.ExtinctionPooling)
    vis["extinction_pooling"] = *v.ExtinctionPooling;
  if (v.FilterAngleFraction)
    vis["filter_angle_fraction"] = *v.FilterAngleFraction;
  if (v.Epsilon)
    vis["epsilon"] = *v.Epsilon;
  if (v.CellMode)
    vis["cell_mode"] = *v.CellMode;
  if (v.SkipUnlitDirections)
    vis["skip_unlit_directions"] = *v.SkipUnlitDirections;
  if (v.Progressive)
    vis["progressive"] = *v.Progressive;
  if (v.LightWeightedDirections)
    vis["light_weighted_directions"] = *v.LightWeightedDirections;
  if (v.FillUnswept)
    vis["fill_unswept"] = *v.FillUnswept;
  if (v.SweepFrameFraction)
    vis["sweep_frame_fraction"] = *v.SweepFrameFraction;
  if (!vis.empty())
  {
    j["visibility"] = vis;
  }

  if (!s.ClipPlanes.empty())
  {
    json planes = json::array();
    for (const auto& p : s.ClipPlanes)
    {
      planes.push_back({ { "origin", Array3(p.Origin) }, { "normal", Array3(p.Normal) } });
    }
    j["clip_planes"] = planes;
  }
  return j;
}
}
