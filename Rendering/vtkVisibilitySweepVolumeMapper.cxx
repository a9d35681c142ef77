#include "vtkVisibilitySweepVolumeMapper.h"

#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsEmissionAbsorptionPass.h"
#include "vsError.h"
#include "vsTransferFunctionTable.h"
#include "vsVolumeInput.h"
#include "vsVolumeScene.h"
#include "vsWindowCompositor.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <glm/gtc/type_ptr.hpp>

vtkStandardNewMacro(vtkVisibilitySweepVolumeMapper);

struct vtkVisibilitySweepVolumeMapper::Internals
{
  std::shared_ptr<vs::Context> Context;
  std::unique_ptr<vs::VolumeScene> Scene;
  std::unique_ptr<vs::EmissionAbsorptionPass> EA;
  std::string LastError;
  uint32_t Frame = 0;
};

vtkVisibilitySweepVolumeMapper::vtkVisibilitySweepVolumeMapper()
  : Impl(new Internals)
{
}

vtkVisibilitySweepVolumeMapper::~vtkVisibilitySweepVolumeMapper() = default;

const char* vtkVisibilitySweepVolumeMapper::GetLastError()
{
  return this->Impl->LastError.c_str();
}

void vtkVisibilitySweepVolumeMapper::ReportError(const std::string& message)
{
  this->Impl->LastError = message;
  vtkErrorMacro(<< message);
}

void vtkVisibilitySweepVolumeMapper::ReleaseGraphicsResources(vtkWindow*)
{
  // The device resources are not tied to the OpenGL context: they stay until the mapper goes.
}

void vtkVisibilitySweepVolumeMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  Internals& I = *this->Impl;
  vtkImageData* input = vtkImageData::SafeDownCast(this->GetInput());
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
  std::string problem = vs::CheckImage(input, scalars);
  if (problem.empty())
  {
    problem = vs::CheckProperty(vol ? vol->GetProperty() : nullptr);
  }
  if (!problem.empty())
  {
    this->ReportError(problem);
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
    vs::VolumeScene::Changes changes =
      I.Scene->Update(input, scalars, vol->GetProperty(), vol->GetMatrix(), this->DensityScale);
    if (changes.Data)
    {
      ++this->VolumeUploadCount;
      if (I.Scene->Volume().NonFiniteCount())
      {
        vtkWarningMacro(<< I.Scene->Volume().NonFiniteCount()
                        << " voxels are NaN or infinite; they are rendered as empty space");
      }
    }
    const vs::VolumeGeometry& geometry = I.Scene->Geometry();

    vs::Viewport vp = vs::WindowCompositor::GetViewport(ren);
    if (vp.Width <= 0 || vp.Height <= 0)
    {
      return;
    }
    std::vector<float> depth = vs::WindowCompositor::ReadDepth(ren, vp);

    vs::shared::VsFrameParams p{};
    double aspect = double(vp.Width) / double(vp.Height);
    vtkMatrix4x4* viewProj = ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
    glm::dmat4 vpm;
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        vpm[c][r] = viewProj->GetElement(r, c);
      }
    }
    p.invViewProj = glm::mat4(glm::inverse(vpm));
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
    if (this->ClippingPlanes)
    {
      int n = std::min(6, this->ClippingPlanes->GetNumberOfItems());
      if (this->ClippingPlanes->GetNumberOfItems() > 6)
      {
        vtkWarningMacro(<< "only the first 6 clipping planes are used");
      }
      for (int i = 0; i < n; ++i)
      {
        vtkPlane* plane = this->ClippingPlanes->GetItem(i);
        double nrm[3], o[3];
        plane->GetNormal(nrm);
        plane->GetOrigin(o);
        p.clipPlanes[i] = glm::vec4(nrm[0], nrm[1], nrm[2], -(nrm[0] * o[0] + nrm[1] * o[1] + nrm[2] * o[2]));
      }
      p.counts.x = static_cast<uint32_t>(n);
    }

    if (!I.EA)
    {
      I.EA = std::make_unique<vs::EmissionAbsorptionPass>(I.Context);
    }
    std::vector<float> rgba = I.EA->Render(I.Scene->Volume(), I.Scene->TF(), p, depth);
    this->LastDeviceSeconds = I.EA->LastSeconds();
    vs::WindowCompositor::Draw(ren, vp, rgba);
    I.LastError.clear();
  }
  catch (const std::exception& e)
  {
    this->ReportError(std::string("VisSweep cannot render: ") + e.what());
  }
}

void vtkVisibilitySweepVolumeMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << this->RenderMode << "\n";
  os << indent << "SampleDistance: " << this->SampleDistance << "\n";
  os << indent << "DensityScale: " << this->DensityScale << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "VolumeUploadCount: " << this->VolumeUploadCount << "\n";
}
