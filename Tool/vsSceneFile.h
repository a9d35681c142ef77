// vsSceneFile.h — the scene file of docs/reference.md ("The scene file") as a plain C++ value:
// parsing (strict: unknown keys and bad values throw std::runtime_error naming the
// key path, e.g. "render.strategy: unknown strategy 'foo' (...)") and writing back
// (ParseScene(ToJson(s), dir) == s). No VTK here: vsRenderCommand builds the
// pipeline from a Scene.
//
// The keys of each section, their types, ranges and defaults: the table of vsSceneSchema.h,
// which the parser checks values by; docs/reference.md documents the same keys (a test compares).
#ifndef vsSceneFile_h
#define vsSceneFile_h

#include "vsSceneSchema.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace vstool
{
using Vec3 = std::array<double, 3>;

struct Scene
{
  struct VolumeSection
  {
    std::string File;               // one file (or a DICOM folder); absolute after parsing
    std::vector<std::string> Files; // or a .vdb sequence; absolute after parsing
    std::string Grid = "density";
    int TimeStep = 0;
    bool operator==(const VolumeSection& o) const;
  };
  struct TransferFunctionSection
  {
    std::vector<std::array<double, 2>> Opacity; // (scalar, alpha), scalars strictly increasing
    std::vector<std::array<double, 4>> Color;   // (scalar, r, g, b) albedo; empty = white
    double UnitDistance = 1.0;
    double DensityScale = 1.0;
    bool Nearest = false; // "interpolation": "nearest" (label maps); default "linear"
    // issue 38: the property's shading (Shade, Ambient, Diffuse, Specular, SpecularPower; VTK's defaults).
    bool Shade = false;
    double Ambient = 0.1, Diffuse = 0.7, Specular = 0.2, SpecularPower = 10.0;
    // (|grad s| per world unit, opacity factor), magnitudes strictly increasing; empty = none
    std::vector<std::array<double, 2>> GradientOpacity;
    bool operator==(const TransferFunctionSection& o) const;
  };
  struct EnvironmentSection
  {
    enum class Kind
    {
      File,
      Constant,
      Sun,
      TwoTone
    };
    Kind Type = Kind::Constant;
    std::string File;            // Kind::File; absolute after parsing
    Vec3 Constant{ 1, 1, 1 };    // Kind::Constant
    Vec3 SunDirection{ 1, 0, 1 };
    double SunRadiusDeg = 0.27;
    Vec3 SunRadiance{ 1000, 1000, 1000 };
    Vec3 SunSky{ 0, 0, 0 };
    Vec3 Upper{ 1, 1, 1 };       // Kind::TwoTone
    Vec3 Lower{ 0, 0, 0 };
    int OctahedralSize = 0;      // 0 = the reader's / source's default
    double RotationDeg = 0.0;    // Kind::File only (rotation about +Z)
    double Intensity = 1.0;
    bool VisibleBackground = true;
    Vec3 Background{ 0, 0, 0 };
    bool operator==(const EnvironmentSection& o) const;
  };
  struct CameraSection
  {
    Vec3 Position{ 0, 0, 1 };
    Vec3 FocalPoint{ 0, 0, 0 };
    Vec3 ViewUp{ 0, 0, 1 };
    double ViewAngle = 30.0;
    std::optional<double> ParallelScale;
    bool Reset = false; // no "camera" in the file: look along +Y, +Z up, framing the volume (ResetCamera)
    bool operator==(const CameraSection& o) const;
  };
  struct RenderSection
  {
    int Width = 512;
    int Height = 512;
    int Spp = 64;
    std::string Strategy = "auto";
    int Seed = 1;
    double Exposure = 1.0;
    bool ToneMapping = true;
    std::string UpdateScheme = "round-robin"; // lazy visibility updates between time steps (the default)
    int DirectionsPerFrame = 4;
    int StaticInterval = 16;
    // The trackers' control extinction (vtkVisibilitySweepVolumeMapper::ControlExtinction):
    // "none", "shadow" (residual ratio tracking), "camera" (decomposition tracking) or "both".
    std::string ControlExtinction = "shadow";
    // The shadow rays' estimator (vtkVisibilitySweepVolumeMapper::TransmittanceEstimator):
    // "ratio-tracking" (residual with the shadow rays' control) or "ray-marching" (Kettunen et al. 2021).
    std::string TransmittanceEstimator = "ratio-tracking";
    // vtkVisibilitySweepVolumeMapper::Sampler: "independent" or "sobol".
    std::string Sampler = "sobol";
    // Shadow rays per scatter point (vtkVisibilitySweepVolumeMapper::ShadowRays, 1-64: splitting).
    int ShadowRays = 1;
    // Full transport (vtkVisibilitySweepVolumeMapper::MaximumScatteringEvents, 1-100000; 1: single
    // scattering) and the phase function's anisotropy (ScatteringAnisotropy, in (-1, 1)).
    int MaxScatteringEvents = 1024;
    double Anisotropy = 0.0;
    double VolumetricScatteringBlending = 0.0; // issue 38: the mapper's, with transfer_function.shade
    // vtkVisibilitySweepVolumeMapper::RenderMode: "monte-carlo", "preview", "ambient-occlusion" or
    // "emission-absorption".
    std::string Mode = "monte-carlo";
    bool operator==(const RenderSection& o) const;
  };
  struct VisibilitySection
  {
    std::optional<int> DirectionResolution; // 4, 8 or 16
    std::optional<double> VoxelsPerCell;
    std::optional<int> KernelResolution;
    std::optional<int> ExtinctionPooling; // voxels per pooled texel of the sweeps' extinction (0 = half a cell)
    std::optional<bool> Filtering;
    std::optional<double> FilterAngleFraction;
    std::optional<double> Epsilon;
    std::optional<std::string> CellMode; // "trilinear" | "stochastic"
    std::optional<bool> SkipUnlitDirections; // default true: directions without light are not swept
    std::optional<bool> Progressive;         // default true: the grid fills in between frames
    std::optional<double> SweepFrameFraction; // default 0.25: sweep time per frame / render time
    std::optional<bool> LightWeightedDirections; // default true: sweep towards each texel's light
    std::optional<bool> FillUnswept; // default true: unswept directions read the nearest swept one
    bool operator==(const VisibilitySection& o) const;
  };
  struct ClipPlane
  {
    Vec3 Origin{ 0, 0, 0 };
    Vec3 Normal{ 0, 0, 1 };
    bool operator==(const ClipPlane& o) const;
  };
  // issue 38: a vtkLight of the renderer (docs/reference.md, "VTK's lights").
  struct Light
  {
    std::string Type = "directional"; // "directional" | "positional" | "spot"
    Vec3 Position{ 0, 0, 1 };         // vtkLight's defaults
    std::optional<Vec3> Direction;    // directional only, instead of Position: towards the light
    Vec3 FocalPoint{ 0, 0, 0 };
    Vec3 Color{ 1, 1, 1 };
    double Intensity = 1.0;
    double ConeAngle = 30.0;          // spot only
    double Exponent = 1.0;            // spot only
    Vec3 Attenuation{ 1, 0, 0 };      // positional and spot only
    bool FollowCamera = false;        // a camera light
    bool operator==(const Light& o) const;
  };

  VolumeSection Volume;
  TransferFunctionSection TransferFunction;
  EnvironmentSection Environment;
  CameraSection Camera;
  RenderSection Render;
  VisibilitySection Visibility;
  std::vector<ClipPlane> ClipPlanes;
  std::vector<Light> Lights;

  bool operator==(const Scene& o) const;
  bool operator!=(const Scene& o) const { return !(*this == o); }
};

/** A direction as a unit vector, computed in double without overflow or underflow (scaled by its
 *  largest component first): directions (sun, view up, clip-plane normals) are kept as written in
 *  the scene and normalised when used, so (1e300, 0, 0) is +X. Zero or non-finite: returned as is. */
Vec3 Normalized(const Vec3& direction);

/** The mapper's enum value of a strategy name: the scene file's ("two-step") or the API's
 *  ("TwoStep"; case, '-' and '_' do not matter); throws std::runtime_error naming `key` if unknown. */
int StrategyIndex(const std::string& name, const std::string& key = "render.strategy");

/** The mapper's enum value of an update scheme name; throws std::runtime_error naming `key` if unknown. */
int UpdateSchemeIndex(const std::string& name, const std::string& key = "render.update_scheme");
int ControlExtinctionIndex(const std::string& name, const std::string& key = "render.control_extinction");
int TransmittanceEstimatorIndex(const std::string& name, const std::string& key = "render.transmittance_estimator");
int SamplerIndex(const std::string& name, const std::string& key = "render.sampler");
int RenderModeIndex(const std::string& name, const std::string& key = "render.mode");

/** Parses a scene; relative paths resolve against baseDir. Throws std::runtime_error naming the key path. */
Scene ParseScene(const nlohmann::json& j, const std::string& baseDir);
/** Parses JSON text (syntax errors are reported with their position). */
Scene ParseSceneText(const std::string& text, const std::string& baseDir);
/** Reads a scene file; errors are prefixed with the file name. */
Scene ReadSceneFile(const std::string& path);

/** The scene as JSON (paths as stored, i.e. absolute after parsing). */
nlohmann::json ToJson(const Scene& scene);
}

#endif
