// vsSceneWrite.cxx — a Scene back to JSON (ToJson) and the equality of scenes, which together
// promise the round trip ParseScene(ToJson(s), dir) == s (vsSceneFile.h).
#include "vsSceneFile.h"

#include <tuple>

namespace vstool
{
using json = nlohmann::json;

namespace
{
json Array3(const Vec3& v)
{
  return json::array({ v[0], v[1], v[2] });
}
}

bool Scene::VolumeSection::operator==(const VolumeSection& o) const
{
  return std::tie(File, Files, Grid, TimeStep) == std::tie(o.File, o.Files, o.Grid, o.TimeStep);
}

bool Scene::TransferFunctionSection::operator==(const TransferFunctionSection& o) const
{
  return std::tie(Opacity, Color, UnitDistance, DensityScale, Nearest, GradientOpacity, Shade, Ambient, Diffuse,
           Specular, SpecularPower) ==
    std::tie(o.Opacity, o.Color, o.UnitDistance, o.DensityScale, o.Nearest, o.GradientOpacity, o.Shade, o.Ambient,
      o.Diffuse, o.Specular, o.SpecularPower);
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
           StaticInterval, ControlExtinction, TransmittanceEstimator, Sampler, ShadowRays, Mode, MaxScatteringEvents,
           Anisotropy) ==
    std::tie(o.Width, o.Height, o.Spp, o.Strategy, o.Seed, o.Exposure, o.ToneMapping, o.UpdateScheme,
      o.DirectionsPerFrame, o.StaticInterval, o.ControlExtinction, o.TransmittanceEstimator, o.Sampler,
      o.ShadowRays, o.Mode, o.MaxScatteringEvents, o.Anisotropy) &&
    VolumetricScatteringBlending == o.VolumetricScatteringBlending; // issue 38
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

bool Scene::Light::operator==(const Light& o) const
{
  return std::tie(Type, Position, Direction, FocalPoint, Color, Intensity, ConeAngle, Exponent, Attenuation,
           FollowCamera) == std::tie(o.Type, o.Position, o.Direction, o.FocalPoint, o.Color, o.Intensity, o.ConeAngle,
                                o.Exponent, o.Attenuation, o.FollowCamera);
}

bool Scene::operator==(const Scene& o) const
{
  return Volume == o.Volume && TransferFunction == o.TransferFunction && Environment == o.Environment &&
    Camera == o.Camera && Render == o.Render && Visibility == o.Visibility && ClipPlanes == o.ClipPlanes &&
    Lights == o.Lights;
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
  // issue 38: the property's shading.
  tf["shade"] = s.TransferFunction.Shade;
  tf["ambient"] = s.TransferFunction.Ambient;
  tf["diffuse"] = s.TransferFunction.Diffuse;
  tf["specular"] = s.TransferFunction.Specular;
  tf["specular_power"] = s.TransferFunction.SpecularPower;
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
    { "shadow_rays", s.Render.ShadowRays }, { "mode", s.Render.Mode },
    { "max_scattering_events", s.Render.MaxScatteringEvents }, { "anisotropy", s.Render.Anisotropy },
    { "volumetric_scattering_blending", s.Render.VolumetricScatteringBlending } /* issue 38 */ };

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
  if (!s.Lights.empty())
  {
    json lights = json::array();
    for (const auto& l : s.Lights)
    {
      json light = { { "type", l.Type }, { "focal_point", Array3(l.FocalPoint) }, { "color", Array3(l.Color) },
        { "intensity", l.Intensity }, { "follow_camera", l.FollowCamera } };
      if (l.Direction)
      {
        light["direction"] = Array3(*l.Direction);
      }
      else
      {
        light["position"] = Array3(l.Position);
      }
      if (l.Type == "spot")
      {
        light["cone_angle"] = l.ConeAngle;
        light["exponent"] = l.Exponent;
      }
      if (l.Type != "directional")
      {
        light["attenuation"] = Array3(l.Attenuation);
      }
      lights.push_back(light);
    }
    j["lights"] = lights;
  }
  return j;
}
}
