#include "vsEnvironmentBackground.h"

#include "vtkEnvironmentMapAlgorithm.h"
#include "vtkEnvironmentMapBackground.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkSkybox.h"
#include "vtkSmartPointer.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"

#include <map>

namespace vs
{
namespace
{
struct Entry
{
  unsigned long StartTag = 0, DeleteTag = 0;
  vtkSmartPointer<vtkEnvironmentMapBackground> Image; // made on first need
  vtkSmartPointer<vtkSkybox> Sky;
  bool InFrame = false;
};

// One entry per observed renderer, removed by the renderer's DeleteEvent (rendering is single
// threaded, as VTK's is).
std::map<vtkRenderer*, Entry>& Entries()
{
  static std::map<vtkRenderer*, Entry> entries;
  return entries;
}

// The mapper whose environment the background shows: that of the first visible volume, in the
// renderer's prop order, whose VisSweep mapper wants it.
vtkVisibilitySweepVolumeMapper* WantingMapper(vtkRenderer* ren)
{
  vtkNew<vtkVolumeCollection> volumes;
  vtkCollectionSimpleIterator pit;
  vtkProp* prop;
  vtkPropCollection* props = ren->GetViewProps();
  for (props->InitTraversal(pit); (prop = props->GetNextProp(pit));)
  {
    if (prop->GetVisibility())
    {
      prop->GetVolumes(volumes);
    }
  }
  vtkCollectionSimpleIterator vit;
  vtkVolume* volume;
  for (volumes->InitTraversal(vit); (volume = volumes->GetNextVolume(vit));)
  {
    auto* mapper = vtkVisibilitySweepVolumeMapper::SafeDownCast(volume->GetMapper());
    if (volume->GetVisibility() && mapper && mapper->GetShowsEnvironmentAsBackground())
    {
      return mapper;
    }
  }
  return nullptr;
}

// A visible vtkSkybox of the user's in the renderer (not `managed`).
bool HasOwnSkybox(vtkRenderer* ren, vtkSkybox* managed)
{
  vtkCollectionSimpleIterator pit;
  vtkProp* prop;
  vtkPropCollection* props = ren->GetViewProps();
  for (props->InitTraversal(pit); (prop = props->GetNextProp(pit));)
  {
    if (prop != managed && prop->GetVisibility() && vtkSkybox::SafeDownCast(prop))
    {
      return true;
    }
  }
  return false;
}

// At the start of a frame, before the renderer collects its visible props: the skybox is in the
// renderer for this frame exactly when a mapper wants it and the user has no skybox of their own.
void StartFrame(vtkRenderer* ren, Entry& e)
{
  vtkVisibilitySweepVolumeMapper* mapper = WantingMapper(ren);
  if (mapper && mapper->GetNumberOfInputConnections(1) > 0 &&
    !vtkEnvironmentMapAlgorithm::IsEnvironmentMapImage(vtkImageData::SafeDownCast(mapper->GetInputDataObject(1, 0))))
  {
    // An environment input that is no map (a failed reader, an image of another kind): the mapper
    // renders nothing and says why, once; the background is the renderer's own. The skybox drew
    // blocky garbage, and its filter logged pipeline errors at every frame.
    mapper = nullptr;
  }
  const bool own = HasOwnSkybox(ren, e.Sky);
  if (mapper && !own)
  {
    if (!e.Sky)
    {
      e.Image = vtkSmartPointer<vtkEnvironmentMapBackground>::New();
      e.Sky = vtkSmartPointer<vtkSkybox>::New();
      e.Image->ConfigureSkybox(e.Sky);
      e.Sky->PickableOff(); // never picked or selected (vtkHardwareSelector skips unpickable props)
    }
    // The mapper's environment (none: its constant white sky) and display transform, every frame:
    // the filter re-runs only when they changed (a new exposure shows in the frame that renders it).
    e.Image->SetInputConnection(
      mapper->GetNumberOfInputConnections(1) > 0 ? mapper->GetInputConnection(1, 0) : nullptr);
    e.Image->CopyDisplaySettings(mapper);
    if (!ren->HasViewProp(e.Sky))
    {
      ren->AddActor(e.Sky);
    }
    e.InFrame = true;
    return;
  }
  if (e.Sky && ren->HasViewProp(e.Sky))
  {
    ren->RemoveActor(e.Sky);
  }
  // Nothing left behind: the skybox, its texture and the hold on the environment's pipeline go.
  e.Sky = nullptr;
  e.Image = nullptr;
  e.InFrame = own;
}

void OnRendererEvent(vtkObject* caller, unsigned long event, void*, void*)
{
  auto* ren = static_cast<vtkRenderer*>(caller);
  auto it = Entries().find(ren);
  if (it == Entries().end())
  {
    return;
  }
  if (event == vtkCommand::DeleteEvent)
  {
    Entries().erase(it);
  }
  else
  {
    StartFrame(ren, it->second);
  }
}
}

void EnvironmentBackground::Observe(vtkRenderer* ren)
{
  if (!ren || Entries().count(ren))
  {
    return;
  }
  vtkNew<vtkCallbackCommand> callback;
  callback->SetCallback(OnRendererEvent);
  Entry e;
  // Before vs::RendererFrame's observer of the same event (a higher priority runs first): the order
  // does not matter today, but the background is the frame's first business.
  e.StartTag = ren->AddObserver(vtkCommand::StartEvent, callback, 1.0f);
  e.DeleteTag = ren->AddObserver(vtkCommand::DeleteEvent, callback);
  Entries().emplace(ren, e);
}

bool EnvironmentBackground::InFrame(vtkRenderer* ren)
{
  auto it = Entries().find(ren);
  return it != Entries().end() && it->second.InFrame;
}

vtkSkybox* EnvironmentBackground::ManagedSkybox(vtkRenderer* ren)
{
  auto it = Entries().find(ren);
  return it != Entries().end() && it->second.Sky && ren->HasViewProp(it->second.Sky) ? it->second.Sky.Get()
                                                                                    : nullptr;
}

int EnvironmentBackground::ObservedRenderers()
{
  return int(Entries().size());
}
}
