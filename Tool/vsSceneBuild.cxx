// vsSceneBuild.cxx — the VTK pipeline of a Scene (vsSceneBuild.h): the volume read within the
// device's limits, the volume property, the environment map, the configured mapper, the camera and
// the offscreen window.
#include "vsSceneBuild.h"
#include "vsDisplayCheck.h"
#include "vsRenderTargetLimits.h"
#include "vsToolVolume.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsError.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkEnvironmentMapSource.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVisSweepHeadlessWindow.h"
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace vstool
{
namespace
{
// Turns an algorithm's vtkErrorMacro messages into the text of an exception.
class ErrorCollector
{
public:
  explicit ErrorCollector(vtkObject* object)
    : Object(object)
  {
    this->Observer->SetCallback(&ErrorCollector::Collect);
    this->Observer->SetClientData(&this->Messages);
    this->Tag = object->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  ~ErrorCollector() { this->Object->RemoveObserver(this->Tag); }
  const std::string& Text() const { return this->Messages; }

private:
  static void Collect(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* messages = static_cast<std::string*>(clientData);
    if (!callData)
    {
      return;
    }
    std::string m(static_cast<const char*>(callData));
    const auto colon = m.find("): ");
    if (colon != std::string::npos)
    {
      m = m.substr(colon + 3);
    }
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
    {
      m.pop_back();
    }
    *messages += (messages->empty() ? "" : "; ") + m;
  }

  vtkObject* Object;
  vtkNew<vtkCallbackCommand> Observer;
  std::string Messages;
  unsigned long Tag = 0;
};
}

vtkSmartPointer<vtkVolumeProperty> MakeVolumeProperty(const Scene& scene)
{
  const auto& tf = scene.TransferFunction;
  auto property = vtkSmartPointer<vtkVolumeProperty>::New();
  vtkNew<vtkPiecewiseFunction> opacity;
  for (const auto& p : tf.Opacity)
  {
    opacity->AddPoint(p[0], p[1]);
  }
  vtkNew<vtkColorTransferFunction> color;
  if (tf.Color.empty())
  {
    color->AddRGBPoint(tf.Opacity.empty() ? 0.0 : tf.Opacity.front()[0], 1.0, 1.0, 1.0);
  }
  for (const auto& p : tf.Color)
  {
    color->AddRGBPoint(p[0], p[1], p[2], p[3]);
  }
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(tf.UnitDistance);
  if (!tf.GradientOpacity.empty())
  {
    vtkNew<vtkPiecewiseFunction> gradient; // opacity x gradient-opacity(|grad s|), as VTK
    for (const auto& p : tf.GradientOpacity)
    {
      gradient->AddPoint(p[0], p[1]);
    }
    property->SetGradientOpacity(gradient);
  }
  if (tf.Nearest)
  {
    property->SetInterpolationTypeToNearest(); // label maps: no blended labels between regions
  }
  else
  {
    property->SetInterpolationTypeToLinear();
  }
  // issue 38: the property's shading (the surface lobe in the Monte Carlo mode, Phong in the emission-absorption mode).
  property->SetShade(tf.Shade ? 1 : 0);
  property->SetAmbient(tf.Ambient);
  property->SetDiffuse(tf.Diffuse);
  property->SetSpecular(tf.Specular);
  property->SetSpecularPower(tf.SpecularPower);
  return property;
}

vtkSmartPointer<vtkAlgorithm> MakeEnvironment(const Scene& scene)
{
  const auto& e = scene.Environment;
  using Kind = Scene::EnvironmentSection::Kind;
  vtkSmartPointer<vtkAlgorithm> algorithm;
  std::string what;
  if (e.Type == Kind::File)
  {
    auto reader = vtkSmartPointer<vtkEnvironmentMapReader>::New();
    reader->SetFileName(e.File.c_str());
    reader->SetRotationDegrees(e.RotationDeg);
    reader->SetOctahedralSize(e.OctahedralSize);
    algorithm = reader;
    what = "environment.file '" + e.File + "'";
  }
  else
  {
    auto source = vtkSmartPointer<vtkEnvironmentMapSource>::New();
    switch (e.Type)
    {
      case Kind::Constant:
        source->SetTypeToConstant();
        source->SetColor(e.Constant.data());
        break;
      case Kind::Sun:
        source->SetTypeToSunDisk();
        source->SetSunDirection(Normalized(e.SunDirection).data()); // (1e300, 0, 0) is +X, not inf
        source->SetSunAngularRadius(e.SunRadiusDeg);
        source->SetSunRadiance(e.SunRadiance.data());
        source->SetSkyColor(e.SunSky.data());
        break;
      default:
        source->SetTypeToTwoToneSky();
        source->SetUpperColor(e.Upper.data());
        source->SetLowerColor(e.Lower.data());
        break;
    }
    if (e.OctahedralSize > 0)
    {
      source->SetOctahedralSize(e.OctahedralSize);
    }
    algorithm = source;
    what = "environment";
  }
  ErrorCollector errors(algorithm);
  ErrorCollector executiveErrors(algorithm->GetExecutive());
  algorithm->Update();
  auto* image = vtkImageData::SafeDownCast(algorithm->GetOutputDataObject(0));
  if (!errors.Text().empty() || !executiveErrors.Text().empty() || !image || image->GetNumberOfPoints() == 0)
  {
    std::string reason = errors.Text().empty() ? executiveErrors.Text() : errors.Text();
    throw std::runtime_error(what + ": cannot build the environment map" + (reason.empty() ? "" : ": " + reason));
  }
  return algorithm;
}

void ConfigureMapper(vtkVisibilitySweepVolumeMapper* mapper, const Scene& scene)
{
  mapper->SetRenderMode(RenderModeIndex(scene.Render.Mode));
  // The tool writes its outputs before the window goes: completing and downloading the grid at exit
  // would only delay it (issue 39).
  mapper->ReleaseKeepsVisibilityGridOff();
  mapper->SetSamplingStrategy(StrategyIndex(scene.Render.Strategy));
  mapper->SetSeed(scene.Render.Seed);
  mapper->SetMaximumSamples(scene.Render.Spp);
  mapper->SetDensityScale(scene.TransferFunction.DensityScale);
  mapper->SetEnvironmentIntensity(scene.Environment.Intensity);
  mapper->SetEnvironmentVisible(scene.Environment.VisibleBackground);
  // The tool's window holds the volume alone: its PNG is the display transform of the radiance, the
  // environment included, as the volume paints it (not the 8-bit lat-long image of a skybox).
  mapper->SetEnvironmentAsBackground(false);
  mapper->SetExposure(scene.Render.Exposure);
  mapper->SetToneMapping(scene.Render.ToneMapping);
  mapper->SetUpdateScheme(UpdateSchemeIndex(scene.Render.UpdateScheme));
  mapper->SetControlExtinction(ControlExtinctionIndex(scene.Render.ControlExtinction));
  mapper->SetTransmittanceEstimator(TransmittanceEstimatorIndex(scene.Render.TransmittanceEstimator));
  mapper->SetSampler(SamplerIndex(scene.Render.Sampler));
  mapper->SetShadowRays(scene.Render.ShadowRays);
  mapper->SetMaximumScatteringEvents(scene.Render.MaxScatteringEvents);
  mapper->SetScatteringAnisotropy(scene.Render.Anisotropy);
  mapper->SetVolumetricScatteringBlending(scene.Render.VolumetricScatteringBlending); // issue 38
  mapper->SetDirectionsPerFrame(scene.Render.DirectionsPerFrame);
  mapper->SetStaticInterval(scene.Render.StaticInterval);
  const auto& v = scene.Visibility;
  if (v.DirectionResolution)
  {
    mapper->SetDirectionResolution(*v.DirectionResolution);
  }
  if (v.VoxelsPerCell)
  {
    mapper->SetVoxelsPerCell(*v.VoxelsPerCell);
  }
  if (v.KernelResolution)
  {
    mapper->SetKernelResolution(*v.KernelResolution);
  }
  if (v.ExtinctionPooling)
  {
    mapper->SetExtinctionPooling(*v.ExtinctionPooling);
  }
  if (v.Filtering)
  {
    mapper->SetFiltering(*v.Filtering);
  }
  if (v.SkipUnlitDirections)
  {
    mapper->SetSkipUnlitDirections(*v.SkipUnlitDirections);
  }
  if (v.Progressive)
  {
    mapper->SetProgressiveVisibility(*v.Progressive);
  }
  if (v.LightWeightedDirections)
  {
    mapper->SetLightWeightedDirections(*v.LightWeightedDirections);
  }
  if (v.FillUnswept)
  {
    mapper->SetFillUnsweptDirections(*v.FillUnswept);
  }
  if (v.SweepFrameFraction)
  {
    mapper->SetSweepFrameFraction(*v.SweepFrameFraction);
  }
  if (v.FilterAngleFraction)
  {
    mapper->SetFilterAngleFraction(*v.FilterAngleFraction);
  }
  if (v.Epsilon)
  {
    mapper->SetVisibilityEpsilon(*v.Epsilon);
  }
  if (v.CellMode)
  {
    mapper->SetCellMode(*v.CellMode == "trilinear" ? vtkVisibilitySweepVolumeMapper::TrilinearCells
                                                   : vtkVisibilitySweepVolumeMapper::StochasticCell);
  }
  mapper->RemoveAllClippingPlanes();
  for (const auto& p : scene.ClipPlanes)
  {
    vtkNew<vtkPlane> plane; // VTK keeps the half-space the normal points into
    plane->SetOrigin(p.Origin.data());
    plane->SetNormal(Normalized(p.Normal).data()); // normalised in double: a normal of 1e300 is no infinity
    mapper->AddClippingPlane(plane);
  }
}

namespace
{
// A volume's dimensions against the device's limits (the volume image) and the host's memory,
// before the reader allocates anything (issue 13, item 7).
std::string VolumeFits(const std::array<int, 3>& dims)
{
  try
  {
    vs::DeviceVolume::CheckFits(*vs::Context::Default(), { uint32_t(dims[0]), uint32_t(dims[1]), uint32_t(dims[2]) });
  }
  catch (const vs::Error& e)
  {
    return e.what();
  }
  // The reader's values (up to 8 bytes a voxel), their float copy and the upload's staging.
  const uint64_t voxels = uint64_t(dims[0]) * uint64_t(dims[1]) * uint64_t(dims[2]);
  const uint64_t host = voxels * 16, memory = vs::RenderTargetLimits::HostMemoryBytes();
  if (memory && host > memory / 2)
  {
    return "reading it needs about " + std::to_string(host >> 20) + " MiB of host memory (16 bytes a voxel), more "
      "than half of this host's " + std::to_string(memory >> 20) + " MiB";
  }
  return std::string();
}
}

SceneObjects BuildScene(const Scene& scene, bool openGLWindow)
{
  SceneObjects o;
  // The image size against the device's limits and the host's memory before anything is read or
  // allocated (issue 13, item 7): a 16384 x 16384 window alone is gigabytes of host memory.
  vs::RenderTargetLimits::Check(*vs::Context::Default(), uint32_t(scene.Render.Width), uint32_t(scene.Render.Height));
  o.Property = MakeVolumeProperty(scene);
  o.Mapper = vtkSmartPointer<vtkVisibilitySweepVolumeMapper>::New();
  ConfigureMapper(o.Mapper, scene);
  o.Volume = vtkSmartPointer<vtkVolume>::New();
  o.Volume->SetMapper(o.Mapper);
  o.Volume->SetProperty(o.Property);
  // The renderer and its lights before the read: the kernel compiled during it depends on whether there are
  // lights (its specialization constants).
  o.Renderer = vtkSmartPointer<vtkRenderer>::New();
  const auto& bg = scene.Environment.Background;
  o.Renderer->SetBackground(bg[0], bg[1], bg[2]);
  o.Renderer->AddVolume(o.Volume);
  // issue 38: the scene's lights, as vtkLights of the renderer (the mapper's estimate takes them, beside
  // the environment; docs/reference.md "VTK's lights").
  for (const auto& l : scene.Lights)
  {
    vtkNew<vtkLight> light;
    if (l.FollowCamera)
    {
      light->SetLightTypeToCameraLight();
    }
    else
    {
      light->SetLightTypeToSceneLight();
    }
    light->SetPositional(l.Type != "directional");
    light->SetFocalPoint(l.FocalPoint.data());
    if (l.Direction)
    {
      const Vec3 d = Normalized(*l.Direction);
      const Vec3 p{ l.FocalPoint[0] + d[0], l.FocalPoint[1] + d[1], l.FocalPoint[2] + d[2] };
      light->SetPosition(p.data());
    }
    else
    {
      light->SetPosition(l.Position.data());
    }
    light->SetColor(l.Color.data());
    light->SetIntensity(l.Intensity);
    light->SetConeAngle(l.Type == "spot" ? l.ConeAngle : 90.0); // VTK: a cone of 90 degrees or more is no spot
    light->SetExponent(l.Exponent);
    light->SetAttenuationValues(l.Attenuation.data());
    o.Renderer->AddLight(light);
  }
  // The render kernel's compile (0.7-0.9 s on lavapipe) on the other core while this one reads the
  // voxels (issue 39: ch2better's first frame waited for it after the read and the upload).
  const VolumeHeaderSeen precompile = [&o](const VolumeHeader& h) {
    vtkNew<vtkImageData> shape;
    shape->SetExtent(const_cast<int*>(h.Extent));
    shape->SetSpacing(h.Spacing);
    shape->SetOrigin(h.Origin);
    double range[2] = { 0.0, -1.0 };
    if (h.ScalarType == VTK_UNSIGNED_CHAR || h.ScalarType == VTK_SIGNED_CHAR || h.ScalarType == VTK_CHAR)
    {
      range[0] = vtkDataArray::GetDataTypeMin(h.ScalarType);
      range[1] = vtkDataArray::GetDataTypeMax(h.ScalarType);
    }
    else if (o.Property->GetScalarOpacity())
    {
      o.Property->GetScalarOpacity()->GetRange(range); // the scalars' range is not known before reading
    }
    o.Mapper->PrecompileRenderKernel(o.Volume, shape, h.ScalarType, range[0], range[1], o.Renderer);
  };
  try
  {
    o.Image = scene.Volume.Files.empty()
      ? ReadVolume(scene.Volume.File, scene.Volume.Grid, vtkIdType(1) << 31, VolumeFits, precompile)
      : ReadVolumeSequence(scene.Volume.Files, scene.Volume.Grid, scene.Volume.TimeStep);
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error(std::string(scene.Volume.Files.empty() ? "volume.file: " : "volume.files: ") + e.what());
  }
  vtkDataArray* scalars = o.Image->GetPointData()->GetScalars();
  if (scalars->GetNumberOfComponents() != 1)
  {
    throw std::runtime_error("volume: the scalars have " + std::to_string(scalars->GetNumberOfComponents()) +
      " components (expected 1)");
  }
  o.Environment = MakeEnvironment(scene);
  o.Mapper->SetInputData(o.Image);
  o.Mapper->SetEnvironmentConnection(o.Environment->GetOutputPort());

  vtkCamera* camera = o.Renderer->GetActiveCamera();
  camera->SetPosition(scene.Camera.Position.data());
  camera->SetFocalPoint(scene.Camera.FocalPoint.data());
  camera->SetViewUp(Normalized(scene.Camera.ViewUp).data());
  camera->SetViewAngle(scene.Camera.ViewAngle);
  if (scene.Camera.ParallelScale)
  {
    camera->ParallelProjectionOn();
    camera->SetParallelScale(*scene.Camera.ParallelScale);
  }
  camera->OrthogonalizeViewUp();
  if (scene.Camera.Reset)
  {
    o.Renderer->ResetCamera(); // keeps the default direction (+Y, +Z up), frames the volume's bounds
  }
  o.Renderer->ResetCameraClippingRange();

  if (openGLWindow)
  {
    vs::RequireDisplay();
    o.Window = vtkSmartPointer<vtkRenderWindow>::New();
    o.Window->SetOffScreenRendering(1);
    o.Window->SetMultiSamples(0);
  }
  else
  {
    o.Window = vtkSmartPointer<vtkVisSweepHeadlessWindow>::New(); // Vulkan only: no X display
  }
  o.Window->SetSize(scene.Render.Width, scene.Render.Height);
  o.Window->AddRenderer(o.Renderer);
  return o;
}
}
