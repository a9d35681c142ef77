#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsContext.h"
#include "vsDeviceEnvironment.h"
#include "vsDeviceVolume.h"
#include "vsEmissionAbsorptionPass.h"
#include "vsEnvironmentMap.h"
#include "vsMajorantGrid.h"
#include "vsMonteCarloPass.h"
#include "vsVisibilityGrid.h"
#include "vsVisibilityUpdateScheduler.h"
#include "shared/update_order.h"
#include "vsVisibilityImage.h"
#include "vsError.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeInput.h"
#include "vsVolumeScene.h"
#include "vsWindowCompositor.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkEnvironmentMapAlgorithm.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

vtkStandardNewMacro(vtkVisibilitySweepVolumeMapper);

struct vtkVisibilitySweepVolumeMapper::Internals
{
  std::shared_ptr<vs::Context> Context;
  std::unique_ptr<vs::VolumeScene> Scene;
  std::unique_ptr<vs::EmissionAbsorptionPass> EA;
  std::unique_ptr<vs::MonteCarloPass> MC, Interactive;
  std::unique_ptr<vs::VisibilityGrid> Grid;
  std::unique_ptr<vs::DeviceEnvironment> Environment;
  vtkMTimeType EnvironmentTime = 0;
  bool DefaultEnvironment = false;
  std::vector<double> GridSignature;  // what the grid was computed for (besides extinction)
  bool GridNeedsFull = true;          // extinction or geometry changed since the last full sweep
  int GridUploads = -1;               // the volume upload the grid last saw (lazy updates)
  vs::VolumeGeometry GridGeometry;    // the geometry the grid is computed for (set each frame)
  vs::VisibilityUpdateScheduler Scheduler;
  std::vector<uint8_t> Swept;         // per direction: swept since the last full update (maybe lazily stale)
  std::vector<double> ImageSignature; // what the accumulated image was rendered for
  vtkSmartPointer<vtkImageData> Radiance;
  vtkSmartPointer<vtkImageData> VisibilityImage;
  std::string LastError;
  vtkMTimeType ErrorStamp = 0;        // the inputs' newest modification time when LastError was reported
  vtkMTimeType RenderStamp = 0;       // the same, for the Render() in progress
  uint32_t Frame = 0;
};

namespace
{
// Filmic tone curve (Narkowicz's fit of ACES) and the sRGB transfer function.
float Filmic(float x)
{
  return std::clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}

float ToSRGB(float x)
{
  x = std::clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

// Equal up to rounding: VTK recomputes the camera matrices on some passes (e.g. while
// vtkWindowToImageFilter grabs the window) with last-bit differences that are no change.
bool NearlyEqual(const std::vector<double>& a, const std::vector<double>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (std::abs(a[i] - b[i]) > 1e-6 * std::max({ 1.0, std::abs(a[i]), std::abs(b[i]) }))
    {
      return false;
    }
  }
  return true;
}

// Every value of the render parameters, integers by value: reinterpreting them as floats
// made small integers (the strategy, the cell mode) denormals that NearlyEqual took for 0,
// so switching Uniform -> Environment kept accumulating into the old image.
std::vector<double> RenderSignature(const vs::shared::VsRenderParams& p)
{
  static_assert(sizeof(vs::shared::VsRenderParams) == 2 * 64 + 17 * 16,
    "a member was added to VsRenderParams: add it to the signature");
  std::vector<double> s;
  auto addMat = [&s](const glm::mat4& m) { s.insert(s.end(), &m[0][0], &m[0][0] + 16); };
  auto addVec = [&s](const glm::vec4& v) { s.insert(s.end(), { v.x, v.y, v.z, v.w }); };
  auto addUint = [&s](const glm::uvec4& v) { s.insert(s.end(), { double(v.x), double(v.y), double(v.z), double(v.w) }); };
  addMat(p.invViewProj);
  addMat(p.worldToIndex);
  for (const auto& v : { p.boxMin, p.boxMax, p.dims, p.tf, p.background, p.sampling2, p.cellSize })
  {
    addVec(v);
  }
  for (const auto& v : { p.viewport, p.sampling, p.grid, p.bricks })
  {
    addUint(v);
  }
  for (const auto& v : p.clipPlanes)
  {
    addVec(v);
  }
  return s;
}

glm::dmat4 ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 g;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      g[c][r] = m->GetElement(r, c);
  return g;
}
}

vtkVisibilitySweepVolumeMapper::vtkVisibilitySweepVolumeMapper()
  : FilterAngleFraction(vs::VisibilityGridParameters().FilterAngleFraction)
  , Impl(new Internals)
{
  this->SetNumberOfInputPorts(2);
}

vtkVisibilitySweepVolumeMapper::~vtkVisibilitySweepVolumeMapper() = default;

const char* vtkVisibilitySweepVolumeMapper::GetLastError()
{
  return this->Impl->LastError.c_str();
}

void vtkVisibilitySweepVolumeMapper::ReportError(const std::string& message)
{
  Internals& I = *this->Impl;
  // Once per change: the same error for unchanged inputs is not reported again at every
  // Render() (an application re-rendering a bad volume would flood its log). GetLastError()
  // keeps it, and GetRadiance() has no image until a render succeeds again.
  const bool repeated = message == I.LastError && I.RenderStamp == I.ErrorStamp;
  I.LastError = message;
  I.ErrorStamp = I.RenderStamp;
  I.Radiance = nullptr;
  if (!repeated)
  {
    vtkErrorMacro(<< message);
  }
}

double* vtkVisibilitySweepVolumeMapper::GetBounds()
{
  // NaN bounds made VTK's culler drop the volume before Render(), which then never said why.
  // Uninitialised bounds keep it in the render list: Render() reports the geometry's error
  // (vs::CheckGeometry), once per change.
  double* b = this->Superclass::GetBounds();
  if (b && !std::all_of(b, b + 6, [](double v) { return std::isfinite(v); }))
  {
    vtkMath::UninitializeBounds(this->Bounds);
    return this->Bounds;
  }
  return b;
}

void vtkVisibilitySweepVolumeMapper::ReleaseGraphicsResources(vtkWindow*)
{
  // The device resources are not tied to the OpenGL context: they stay until the mapper goes.
}

void vtkVisibilitySweepVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
  I.RenderStamp = vs::NewestModification({ this, input, vol,
    this->GetNumberOfInputConnections(1) > 0 ? this->GetInputAlgorithm(1, 0) : nullptr });
  int cellFlag = 0;
  vtkDataArray* scalars = input
    ? vtkAbstractMapper::GetScalars(input, this->ScalarMode, this->ArrayAccessMode, this->ArrayId,
        this->ArrayName, cellFlag)
    : nullptr;
  if (scalars && cellFlag)
  {
    this->ReportError("the input volume's scalars are cell data; VisSweep renders point scalars");
    return;
  }
  try
  {
    if (!I.Context)
    {
      I.Context = vs::Context::Default();
    }
    if (!I.Scene)
    {
      I.Scene = std::make_unique<vs::VolumeScene>(I.Context);
    }
    this->DirectionsUpdatedLastFrame = 0;
    this->LastFrameSweepSeconds = 0.0;
    const auto updateStart = std::chrono::steady_clock::now();
    vs::VolumeScene::Changes changes =
      I.Scene->Update(input, scalars, vol ? vol->GetProperty() : nullptr, vol ? vol->GetMatrix() : nullptr,
        this->DensityScale);
    this->LastUpdateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - updateStart).count();
    if (changes.Data)
    {
      ++this->VolumeUploadCount;
      this->LastMajorantSeconds = I.Scene->Majorants().LastSeconds();
      if (I.Scene->Volume().NonFiniteCount())
      {
        vtkWarningMacro(<< I.Scene->Volume().NonFiniteCount()
                        << " voxels are NaN or infinite; they are rendered as empty space");
      }
    }
    // New data under the same transfer function (a new time step) may update the grid lazily;
    // any other change of extinction or geometry needs every direction again.
    if (changes.Geometry || (changes.Extinction && (!changes.Data || changes.TransferFunction)))
    {
      I.GridNeedsFull = true;
    }
    if (this->RenderMode == EmissionAbsorption)
    {
      this->RenderEmissionAbsorption(ren, vol);
    }
    else
    {
      this->RenderMonteCarlo(ren, vol);
    }
    I.LastError.clear();
  }
  catch (const std::exception& e)
  {
    this->ReportError(std::string("VisSweep cannot render: ") + e.what());
  }
}

namespace
{
// The camera and volume placement as the shaders want them.
struct View
{
  vs::Viewport Port;
  glm::mat4 InvViewProj;
};

View MakeView(vtkRenderer* ren)
{
  View v;
  v.Port = vs::WindowCompositor::GetViewport(ren);
  double aspect = v.Port.Height > 0 ? double(v.Port.Width) / double(v.Port.Height) : 1.0;
  v.InvViewProj =
    glm::mat4(glm::inverse(ToGlm(ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1))));
  return v;
}

// World clipping planes (n, w): kept where dot(n, x) + w >= 0.
std::vector<glm::dvec4> WorldPlanes(vtkPlaneCollection* planes)
{
  std::vector<glm::dvec4> out;
  if (!planes)
  {
    return out;
  }
  vtkPlane* plane;
  vtkCollectionSimpleIterator it;
  for (planes->InitTraversal(it); (plane = planes->GetNextPlane(it));)
  {
    double n[3], o[3];
    plane->GetNormal(n);
    plane->GetOrigin(o);
    out.emplace_back(n[0], n[1], n[2], -(n[0] * o[0] + n[1] * o[1] + n[2] * o[2]));
  }
  if (out.size() > 6)
  {
    throw vs::InputError("at most 6 clipping planes are supported, got " + std::to_string(out.size()));
  }
  return out;
}
}

namespace
{
// The volume's geometry with VTK's cropping subvolume applied to its index box.
vs::VolumeGeometry CroppedGeometry(vtkVolumeMapper* mapper, const vs::VolumeGeometry& full)
{
  if (!mapper->GetCropping())
  {
    return full;
  }
  if (mapper->GetCroppingRegionFlags() != VTK_CROP_SUBVOLUME)
  {
    throw vs::InputError("only the cropping subvolume (CroppingRegionFlags = VTK_CROP_SUBVOLUME) is supported, got "
                         "flags " + std::to_string(mapper->GetCroppingRegionFlags()));
  }
  return vs::CropGeometry(full, vtkImageData::SafeDownCast(mapper->GetInput()), mapper->GetCroppingRegionPlanes());
}
}

void vtkVisibilitySweepVolumeMapper::RenderEmissionAbsorption(vtkRenderer* ren, vtkVolume*)
{
  Internals& I = *this->Impl;
  const vs::VolumeGeometry geometry = CroppedGeometry(this, I.Scene->Geometry());
  View view = MakeView(ren);
  vs::Viewport vp = view.Port;
  if (vp.Width <= 0 || vp.Height <= 0)
  {
    return;
  }
  std::vector<float> depth = vs::WindowCompositor::ReadDepth(ren, vp);
  vs::shared::VsFrameParams p{};
  p.invViewProj = view.InvViewProj;
  p.worldToIndex = glm::mat4(geometry.WorldToIndex);
  p.indexToWorld = glm::mat4(geometry.IndexToWorld);
  p.boxMin = glm::vec4(geometry.BoxMin, 0.0f);
  p.boxMax = glm::vec4(geometry.BoxMax, 0.0f);
  p.dims = glm::vec4(geometry.Dims[0], geometry.Dims[1], geometry.Dims[2], 0.0f);
  auto tf = I.Scene->TF().Params();
  p.tf = glm::vec4(tf[0], tf[1], tf[2], tf[3]);
  p.viewport = glm::uvec4(vp.Width, vp.Height, I.Frame++, static_cast<uint32_t>(this->Seed));
  double step = this->SampleDistance > 0.0 ? this->SampleDistance : 0.5 * geometry.MinSpacing;
  p.march = glm::vec4(float(step), 0.995f, 0.0f, 0.0f);
  auto planes = WorldPlanes(this->ClippingPlanes);
  for (size_t i = 0; i < planes.size(); ++i)
  {
    p.clipPlanes[i] = glm::vec4(planes[i]);
  }
  p.counts.x = uint32_t(planes.size());
  if (!I.EA)
  {
    I.EA = std::make_unique<vs::EmissionAbsorptionPass>(I.Context);
  }
  std::vector<float> rgba = I.EA->Render(I.Scene->Volume(), I.Scene->TF(), p, depth);
  this->LastDeviceSeconds = I.EA->LastSeconds();
  vs::WindowCompositor::Draw(ren, vp, rgba);
}

void vtkVisibilitySweepVolumeMapper::RenderMonteCarlo(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  const vs::VolumeGeometry geometry = CroppedGeometry(this, I.Scene->Geometry());
  const bool croppedAway = glm::any(glm::greaterThan(geometry.BoxMin, geometry.BoxMax));

  // The environment: port 1, or a constant white sky.
  vtkImageData* envImage = nullptr;
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    this->GetInputAlgorithm(1, 0)->Update();
    envImage = vtkImageData::SafeDownCast(this->GetInputDataObject(1, 0));
    if (!envImage || envImage->GetNumberOfPoints() == 0)
    {
      throw vs::InputError("the environment input (port 1) has no map; check its reader for errors");
    }
  }
  if (!I.Environment || (envImage && envImage->GetMTime() != I.EnvironmentTime) || (!envImage && !I.DefaultEnvironment))
  {
    std::shared_ptr<const vs::EnvironmentMap> map;
    if (envImage)
    {
      std::string error;
      map = vtkEnvironmentMapAlgorithm::EnvironmentMapFromImage(envImage, &error);
      if (!map)
      {
        throw vs::InputError("the environment input is not an environment map: " + error);
      }
    }
    else
    {
      map = std::make_shared<vs::EnvironmentMap>(vs::EnvironmentMap::Constant(16, glm::vec3(1.0f)));
    }
    I.Environment.reset();
    I.Environment = std::make_unique<vs::DeviceEnvironment>(I.Context, *map, std::max(8, this->DirectionResolution));
    I.EnvironmentTime = envImage ? envImage->GetMTime() : 0;
    I.DefaultEnvironment = envImage == nullptr;
    ++this->EnvironmentUploadCount;
  }

  // The visibility grid, only for the strategies that use it.
  const std::vector<glm::dvec4> planes = WorldPlanes(this->ClippingPlanes);
  const bool emptyVolume = I.Scene->Majorants().MaxMajorant() <= 0.0f || croppedAway;
  const bool needGrid = this->SamplingStrategy >= Visibility && !emptyVolume;
  I.GridGeometry = geometry;
  this->UpdateVisibilityGrid(needGrid);

  // Parameters of this frame.
  View view = MakeView(ren);
  vtkRenderWindow* win = ren->GetRenderWindow();
  const bool interactive = this->InteractiveUpdateRate > 0.0 && win &&
    win->GetDesiredUpdateRate() >= this->InteractiveUpdateRate;
  const int sub = interactive ? this->InteractiveSubsampling : 1;
  vs::Viewport vp = view.Port;
  if (vp.Width <= 0 || vp.Height <= 0)
  {
    return;
  }
  const uint32_t w = uint32_t(std::max(1, vp.Width / sub)), h = uint32_t(std::max(1, vp.Height / sub));
  // Without opaque actors the depth buffer holds nothing of ours to respect; not reading it also
  // keeps passes that re-render the window (vtkWindowToImageFilter) from restarting accumulation.
  std::vector<float> fullDepth = ren->VisibleActorCount() > 0 ? vs::WindowCompositor::ReadDepth(ren, vp)
                                                             : std::vector<float>(size_t(vp.Width) * vp.Height, 1.0f);
  std::vector<float> depth(size_t(w) * h);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      depth[size_t(y) * w + x] = fullDepth[size_t(std::min<uint32_t>(y * sub, vp.Height - 1)) * vp.Width +
        std::min<uint32_t>(x * sub, vp.Width - 1)];

  vs::shared::VsRenderParams p{};
  p.invViewProj = view.InvViewProj;
  p.worldToIndex = glm::mat4(geometry.WorldToIndex);
  p.boxMin = glm::vec4(geometry.BoxMin, 0.0f);
  p.boxMax = glm::vec4(geometry.BoxMax, 0.0f);
  p.dims = glm::vec4(geometry.Dims[0], geometry.Dims[1], geometry.Dims[2], 0.0f);
  auto tf = I.Scene->TF().Params();
  p.tf = glm::vec4(tf[0], tf[1], tf[2], tf[3]);
  p.background = glm::vec4(0.0f, 0.0f, 0.0f, this->EnvironmentVisible ? 1.0f : 0.0f);
  p.viewport = glm::uvec4(w, h, 0u, static_cast<uint32_t>(this->Seed));
  uint32_t strategy = emptyVolume ? uint32_t(Uniform) : uint32_t(this->SamplingStrategy);
  p.sampling = glm::uvec4(strategy, 1u, uint32_t(this->CellMode), uint32_t(I.Environment->FinestLevel()));
  // The variance's squares are of radiance relative to the brightest light (no underflow for dim maps).
  const double brightest = I.Environment->MaxLuminance() * this->EnvironmentIntensity;
  const float squareScale = brightest > 0.0 && std::isfinite(1.0 / brightest) && 1.0 / brightest < 1e37
    ? float(1.0 / brightest) : 1.0f;
  p.sampling2 = glm::vec4(float(this->VisibilityEpsilon), float(this->EnvironmentIntensity),
    float(I.Scene->Majorants().BrickSize()), squareScale);
  if (needGrid)
  {
    auto c = I.Grid->Cells();
    p.grid = glm::uvec4(c[0], c[1], c[2], I.Grid->Side());
    p.cellSize = glm::vec4(I.Grid->CellSize(), 0.0f);
  }
  auto b = I.Scene->Majorants().Bricks();
  p.bricks = glm::uvec4(b[0], b[1], b[2], uint32_t(planes.size()));
  const glm::dmat3 m(geometry.IndexToWorld);
  const glm::dvec3 o(geometry.IndexToWorld[3]);
  for (size_t i = 0; i < planes.size(); ++i)
  {
    glm::dvec3 n(planes[i]);
    p.clipPlanes[i] = glm::vec4(glm::vec3(glm::transpose(m) * n), float(glm::dot(n, o) + planes[i].w));
  }

  vs::MonteCarloPass* pass = nullptr;
  if (interactive)
  {
    if (!I.Interactive)
    {
      I.Interactive = std::make_unique<vs::MonteCarloPass>(I.Context);
    }
    pass = I.Interactive.get();
    pass->Reset(w, h);
    I.ImageSignature.clear(); // refine from scratch once the view is still
  }
  else
  {
    if (!I.MC)
    {
      I.MC = std::make_unique<vs::MonteCarloPass>(I.Context);
    }
    pass = I.MC.get();
    // Everything the accumulated image depends on; any difference restarts accumulation.
    std::vector<double> signature = RenderSignature(p);
    signature.push_back(double(I.Scene->TableBuilds()));
    signature.push_back(double(I.Scene->Uploads()));
    signature.push_back(double(this->EnvironmentUploadCount));
    signature.push_back(double(this->VisibilityUpdateCount));
    signature.insert(signature.end(), depth.begin(), depth.end());
    if (!NearlyEqual(signature, I.ImageSignature) || pass->Width() != w || pass->Height() != h)
    {
      pass->Reset(w, h);
      I.ImageSignature = signature;
      ++this->AccumulationResetCount;
    }
  }
  const uint32_t remaining = uint32_t(std::max(0, this->MaximumSamples - int(pass->Samples())));
  const uint32_t spp = interactive ? 1u : std::min<uint32_t>(uint32_t(this->SamplesPerFrame), remaining);
  if (spp > 0)
  {
    p.sampling.y = spp;
    pass->SetCountLookups(this->CountLookups);
    pass->Render(I.Scene->Volume(), I.Scene->TF(), I.Scene->Majorants(), needGrid ? I.Grid.get() : nullptr,
      *I.Environment, p, depth);
    this->LastDeviceSeconds = pass->LastSeconds();
    if (this->CountLookups)
    {
      auto n = pass->LastLookups();
      this->LastLookupCounts[0] = double(n[0]);
      this->LastLookupCounts[1] = double(n[1]);
      this->LastLookupCounts[2] = double(n[2]);
    }
  }
  this->AccumulatedSamples = interactive ? 0 : int(pass->Samples());

  // Keep the linear radiance; show it tone mapped.
  std::vector<float> mean = pass->Mean();
  if (!interactive)
  {
    if (!I.Radiance)
    {
      I.Radiance = vtkSmartPointer<vtkImageData>::New();
    }
    I.Radiance->Initialize();
    I.Radiance->SetDimensions(int(w), int(h), 1);
    vtkNew<vtkFloatArray> rgb;
    rgb->SetName("Radiance");
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(vtkIdType(w) * h);
    vtkNew<vtkFloatArray> alpha;
    alpha->SetName("Alpha");
    alpha->SetNumberOfTuples(vtkIdType(w) * h);
    for (vtkIdType i = 0; i < vtkIdType(w) * h; ++i)
    {
      rgb->SetTuple3(i, mean[4 * i], mean[4 * i + 1], mean[4 * i + 2]);
      alpha->SetValue(i, mean[4 * i + 3]);
    }
    I.Radiance->GetPointData()->SetScalars(rgb);
    I.Radiance->GetPointData()->AddArray(alpha);
  }
  std::vector<float> display(mean.size());
  const float exposure = float(this->Exposure);
  for (size_t i = 0; i < mean.size(); i += 4)
  {
    float a = std::clamp(mean[i + 3], 0.0f, 1.0f);
    for (int c = 0; c < 3; ++c)
    {
      // Premultiplied: tone map the radiance of the covered part, then weigh by coverage.
      float l = a > 0.0f ? exposure * mean[i + c] / a : 0.0f;
      display[i + c] = a * ToSRGB(this->ToneMapping ? Filmic(l) : std::min(l, 1.0f));
    }
    display[i + 3] = a;
  }
  if (sub == 1)
  {
    vs::WindowCompositor::Draw(ren, vp, display);
  }
  else
  {
    vs::WindowCompositor::DrawScaled(ren, vp, display, int(w), int(h));
  }
  (void)vol;
}

namespace
{
vs::VisibilityGridParameters GridParameters(int directionResolution, double voxelsPerCell, int kernelResolution,
  bool filtering, double filterAngleFraction)
{
  vs::VisibilityGridParameters gp;
  gp.DirectionResolution = uint32_t(std::max(0, directionResolution));
  gp.VoxelsPerCell = voxelsPerCell;
  gp.KernelResolution = uint32_t(kernelResolution);
  gp.AutoKernelRaysPerCell = vs::RendererKernelRaysPerCell; // the renderer only samples by the grid
  gp.Filtering = filtering;
  gp.FilterAngleFraction = filterAngleFraction;
  return gp;
}

// Everything the grid's layout depends on besides extinction: parameters, clipping, placement.
std::vector<double> GridSignature(const vs::VisibilityGridParameters& gp, const std::vector<glm::dvec4>& planes,
  const vs::VolumeGeometry& geometry)
{
  std::vector<double> signature = { double(gp.DirectionResolution), gp.VoxelsPerCell, double(gp.KernelResolution),
    double(gp.Filtering), gp.FilterAngleFraction };
  for (const auto& pl : planes)
  {
    signature.insert(signature.end(), { pl.x, pl.y, pl.z, pl.w });
  }
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      signature.push_back(geometry.WorldToIndex[c][r]);
  for (int i = 0; i < 3; ++i)
  {
    signature.insert(signature.end(), { geometry.BoxMin[i], geometry.BoxMax[i] });
  }
  return signature;
}
}

// The directions this render needs swept: all of them, except that Combined and TwoStep never
// read the visibility of a direction whose environment importance at the grid's resolution is 0
// (their product weight is visibility x importance), so with SkipUnlitDirections those are left
// out (DESIGN.md: directions without environment radiance never need sweeping).
std::vector<uint8_t> vtkVisibilitySweepVolumeMapper::RequiredDirections(int side)
{
  Internals& I = *this->Impl;
  std::vector<uint8_t> required(size_t(side) * side, 1);
  if (this->SkipUnlitDirections && (this->SamplingStrategy == Combined || this->SamplingStrategy == TwoStep))
  {
    const std::vector<float> importance = I.Environment->ImportanceLevel(int(vs::shared::vs_log2_pow2(uint32_t(side))));
    for (size_t n = 0; n < required.size() && n < importance.size(); ++n)
    {
      required[n] = importance[n] > 0.0f;
    }
  }
  return required;
}

// Every needed direction when the grid is missing or anything but the data changed since the
// last full sweep; after a data-only change, the needed directions the update scheme picks (maybe
// none); and any needed direction never swept since the last full sweep (the environment or the
// strategy changed what is needed).
void vtkVisibilitySweepVolumeMapper::UpdateVisibilityGrid(bool needGrid)
{
  Internals& I = *this->Impl;
  this->UnlitDirections = 0;
  if (!needGrid)
  {
    return;
  }
  const vs::VisibilityGridParameters gp = GridParameters(
    this->DirectionResolution, this->VoxelsPerCell, this->KernelResolution, this->Filtering, this->FilterAngleFraction);
  const std::vector<double> signature = GridSignature(gp, WorldPlanes(this->ClippingPlanes), I.GridGeometry);
  const std::vector<uint8_t> required = this->RequiredDirections(gp.DirectionResolution);
  this->UnlitDirections = int(std::count(required.begin(), required.end(), uint8_t(0)));
  if (!I.Grid)
  {
    I.Grid = std::make_unique<vs::VisibilityGrid>(I.Context);
  }
  std::vector<uint32_t> directions;
  if (!I.Grid->Valid() || I.GridNeedsFull || signature != I.GridSignature)
  {
    vs::VisibilityGrid::CheckFits(*I.Context, I.GridGeometry, gp);
    I.Grid->Allocate(I.GridGeometry, gp, this->UnlitDirections > 0);
    I.Swept.assign(required.size(), 0);
    I.GridSignature = signature;
    I.GridNeedsFull = false;
    I.Scheduler.OnFullUpdate();
  }
  else if (I.Scene->Uploads() != I.GridUploads)
  {
    vs::UpdateSchedule schedule;
    schedule.Scheme = vs::UpdateScheme(this->UpdateScheme);
    schedule.DirectionsPerFrame = uint32_t(this->DirectionsPerFrame);
    schedule.StaticInterval = uint32_t(this->StaticInterval);
    schedule.Seed = uint32_t(this->Seed);
    std::vector<float> importance;
    if (this->UpdateScheme == EnvironmentGuided)
    {
      importance = I.Environment->ImportanceLevel(int(vs::shared::vs_log2_pow2(gp.DirectionResolution)));
    }
    directions = I.Scheduler.OnDataChange(schedule, gp.DirectionResolution, importance, required);
  }
  I.GridUploads = I.Scene->Uploads();
  // Needed but never swept since the last full sweep (all of them right after one).
  for (uint32_t n = 0; n < required.size(); ++n)
  {
    if (required[n] && !I.Swept[n] && std::find(directions.begin(), directions.end(), n) == directions.end())
    {
      directions.push_back(n);
    }
  }
  if (!directions.empty())
  {
    std::sort(directions.begin(), directions.end());
    this->SweepDirections(directions.size() == required.size() ? std::vector<unsigned int>() : directions);
    for (uint32_t n : directions)
    {
      I.Swept[n] = 1;
    }
  }
}

// Sweeps `directions` of the grid (all when empty) for the current volume and transfer function.
void vtkVisibilitySweepVolumeMapper::SweepDirections(const std::vector<unsigned int>& directions)
{
  Internals& I = *this->Impl;
  const vs::VisibilityGridParameters gp = GridParameters(
    this->DirectionResolution, this->VoxelsPerCell, this->KernelResolution, this->Filtering, this->FilterAngleFraction);
  const auto start = std::chrono::steady_clock::now();
  const uint64_t before = I.Grid->DirectionsComputed();
  this->InvokeEvent(vtkCommand::StartEvent);
  I.Grid->Compute(I.Scene->Volume(), I.Scene->TF(), I.Scene->Majorants(), I.GridGeometry,
    WorldPlanes(this->ClippingPlanes), gp, directions, [this](double f) { this->UpdateProgress(f); });
  this->InvokeEvent(vtkCommand::EndEvent);
  this->LastSweepSeconds = I.Grid->LastSeconds();
  this->LastFrameSweepSeconds = I.Grid->LastSeconds();
  this->DirectionsUpdatedLastFrame = int(I.Grid->DirectionsComputed() - before);
  this->DirectionsUpdatedTotal += this->DirectionsUpdatedLastFrame;
  this->LastUpdateSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++this->VisibilityUpdateCount;
  I.VisibilityImage = nullptr;
}

const char* vtkVisibilitySweepVolumeMapper::GetUpdateSchemeAsString()
{
  switch (this->UpdateScheme)
  {
    case RoundRobin:
      return "RoundRobin";
    case EnvironmentGuided:
      return "EnvironmentGuided";
    case StaticUpdate:
      return "Static";
    default:
      return "Full";
  }
}

vtkImageData* vtkVisibilitySweepVolumeMapper::GetRadiance(bool variance)
{
  Internals& I = *this->Impl;
  if (!I.Radiance || !I.MC)
  {
    return nullptr;
  }
  if (variance)
  {
    // Double: the variance of radiance below ~1e-19 (a dim map in physical units) is below float's range.
    try
    {
      std::vector<double> var = I.MC->Variance();
      vtkNew<vtkDoubleArray> v;
      v->SetName("Variance");
      v->SetNumberOfComponents(4);
      v->SetNumberOfTuples(vtkIdType(var.size() / 4));
      std::copy(var.begin(), var.end(), v->GetPointer(0));
      I.Radiance->GetPointData()->AddArray(v);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< "GetRadiance: cannot read the variance back from the device: " << e.what());
      return nullptr;
    }
  }
  return I.Radiance;
}

vtkImageData* vtkVisibilitySweepVolumeMapper::GetVisibilityGrid()
{
  Internals& I = *this->Impl;
  if (!I.Grid || !I.Grid->Valid() || !I.Scene)
  {
    return nullptr;
  }
  // The renderer may have left directions without environment light unswept: a user asking for
  // the grid gets every direction.
  std::vector<unsigned int> missing;
  for (uint32_t n = 0; n < I.Swept.size(); ++n)
  {
    if (!I.Swept[n])
    {
      missing.push_back(n);
    }
  }
  if (!missing.empty())
  {
    try
    {
      this->SweepDirections(missing);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro("GetVisibilityGrid: sweeping the directions the render skipped failed: " << e.what());
      return nullptr;
    }
    std::fill(I.Swept.begin(), I.Swept.end(), uint8_t(1));
  }
  if (!I.VisibilityImage)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
    try
    {
      // In data coordinates (no prop matrix), over the box the grid covers (cropped or not).
      vs::VisibilityGridToImage(*I.Grid, CroppedGeometry(this, vs::ComputeGeometry(input, nullptr)), image);
    }
    catch (const std::exception& e)
    {
      vtkErrorMacro(<< "GetVisibilityGrid: cannot read the grid back from the device: " << e.what());
      return nullptr;
    }
    I.VisibilityImage = image;
  }
  return I.VisibilityImage;
}

int vtkVisibilitySweepVolumeMapper::GetMajorantUpdateCount()
{
  return this->Impl->Scene && this->Impl->Scene->Ready()
    ? int(this->Impl->Scene->Majorants().MajorantUpdates())
    : 0;
}

void vtkVisibilitySweepVolumeMapper::SetEnvironmentConnection(vtkAlgorithmOutput* port)
{
  this->SetInputConnection(1, port);
}

void vtkVisibilitySweepVolumeMapper::SetEnvironmentData(vtkImageData* environment)
{
  this->SetInputDataInternal(1, environment);
}

int vtkVisibilitySweepVolumeMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

void vtkVisibilitySweepVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << (this->RenderMode == MonteCarlo ? "MonteCarlo" : "EmissionAbsorption") << "\n";
  os << indent << "SamplingStrategy: " << this->SamplingStrategy << "\n";
  os << indent << "CellMode: " << this->CellMode << "\n";
  os << indent << "SamplesPerFrame: " << this->SamplesPerFrame << "\n";
  os << indent << "MaximumSamples: " << this->MaximumSamples << "\n";
  os << indent << "AccumulatedSamples: " << this->AccumulatedSamples << "\n";
  os << indent << "VisibilityEpsilon: " << this->VisibilityEpsilon << "\n";
  os << indent << "DirectionResolution: " << this->DirectionResolution << "\n";
  os << indent << "VoxelsPerCell: " << this->VoxelsPerCell << "\n";
  os << indent << "KernelResolution: " << this->KernelResolution << "\n";
  os << indent << "Filtering: " << this->Filtering << "\n";
  os << indent << "FilterAngleFraction: " << this->FilterAngleFraction << "\n";
  os << indent << "EnvironmentIntensity: " << this->EnvironmentIntensity << "\n";
  os << indent << "EnvironmentVisible: " << this->EnvironmentVisible << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMapping: " << this->ToneMapping << "\n";
  os << indent << "InteractiveUpdateRate: " << this->InteractiveUpdateRate << "\n";
  os << indent << "InteractiveSubsampling: " << this->InteractiveSubsampling << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "VolumeUploadCount: " << this->VolumeUploadCount << "\n";
  os << indent << "LastDeviceSeconds: " << this->LastDeviceSeconds << "\n";
  os << indent << "LastMajorantSeconds: " << this->LastMajorantSeconds << "\n";
  os << indent << "CountLookups: " << this->CountLookups << "\n";
  os << indent << "UpdateScheme: " << this->GetUpdateSchemeAsString() << "\n";
  os << indent << "SkipUnlitDirections: " << (this->SkipUnlitDirections ? "On" : "Off") << "\n";
  os << indent << "UnlitDirections: " << this->UnlitDirections << "\n";
  os << indent << "DirectionsPerFrame: " << this->DirectionsPerFrame << "\n";
  os << indent << "StaticInterval: " << this->StaticInterval << "\n";
  os << indent << "DirectionsUpdatedLastFrame: " << this->DirectionsUpdatedLastFrame << "\n";
  os << indent << "DirectionsUpdatedTotal: " << this->DirectionsUpdatedTotal << "\n";
  os << indent << "VisibilityUpdateCount: " << this->VisibilityUpdateCount << "\n";
}
