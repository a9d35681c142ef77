#include "vsPeelingDeferral.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkInformation.h"
#include "vtkInformationObjectBaseVectorKey.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderPass.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"

namespace vs
{
PeelingDeferral::~PeelingDeferral()
{
  this->Cancel();
}

bool PeelingDeferral::InsidePeeling(vtkVolume* vol)
{
  vtkInformation* info = vol ? vol->GetPropertyKeys() : nullptr;
  if (!info || !info->Has(vtkOpenGLRenderPass::RenderPasses()))
  {
    return false;
  }
  const int n = info->Length(vtkOpenGLRenderPass::RenderPasses());
  for (int i = 0; i < n; ++i)
  {
    if (vtkDualDepthPeelingPass::SafeDownCast(info->Get(vtkOpenGLRenderPass::RenderPasses(), i)))
    {
      return true;
    }
  }
  return false;
}

void PeelingDeferral::Defer(vtkRenderer* ren, std::function<void()> draw)
{
  if (this->Pending.GetPointer() == ren)
  {
    return; // already drawn at this frame's end
  }
  this->Cancel();
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(&PeelingDeferral::OnEnd);
  callback->SetClientData(this);
  this->Tag = ren->AddObserver(vtkCommand::EndEvent, callback);
  this->Pending = ren;
  this->Draw = std::move(draw);
}

void PeelingDeferral::OnEnd(vtkObject* caller, unsigned long, void* self, void*)
{
  auto* d = static_cast<PeelingDeferral*>(self);
  if (caller != d->Pending.GetPointer())
  {
    return;
  }
  std::function<void()> draw = std::move(d->Draw);
  d->Cancel();
  ++d->Count;
  if (draw)
  {
    draw();
  }
}

void PeelingDeferral::Cancel()
{
  if (this->Pending)
  {
    this->Pending->RemoveObserver(this->Tag);
  }
  this->Pending = nullptr;
  this->Tag = 0;
  this->Draw = nullptr;
}
}
