#include "vsRendererFrame.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkRenderer.h"

#include <map>

namespace vs
{
namespace
{
struct Entry
{
  unsigned long StartTag = 0, DeleteTag = 0;
  const void* Owner = nullptr; // who claimed the current frame (nullptr: nobody yet)
};

// One entry per observed renderer, removed by the renderer's DeleteEvent (rendering is single
// threaded, as VTK's is).
std::map<vtkRenderer*, Entry>& Entries()
{
  static std::map<vtkRenderer*, Entry> entries;
  return entries;
}

void OnRendererEvent(vtkObject* caller, unsigned long event, void*, void*)
{
  auto it = Entries().find(static_cast<vtkRenderer*>(caller));
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
    it->second.Owner = nullptr; // a new frame
  }
}
}

bool RendererFrame::Claim(vtkRenderer* ren, const void* owner)
{
  if (!ren)
  {
    return true;
  }
  auto& entries = Entries();
  auto it = entries.find(ren);
  if (it == entries.end())
  {
    vtkNew<vtkCallbackCommand> callback;
    callback->SetCallback(OnRendererEvent);
    Entry e;
    e.StartTag = ren->AddObserver(vtkCommand::StartEvent, callback);
    e.DeleteTag = ren->AddObserver(vtkCommand::DeleteEvent, callback);
    // The frame in progress started before the observer: whoever asks first owns it.
    it = entries.emplace(ren, e).first;
  }
  if (!it->second.Owner)
  {
    it->second.Owner = owner;
  }
  return it->second.Owner == owner;
}

void RendererFrame::Forget(const void* owner)
{
  for (auto& e : Entries())
  {
    if (e.second.Owner == owner)
    {
      e.second.Owner = nullptr;
    }
  }
}

int RendererFrame::ObservedRenderers()
{
  return int(Entries().size());
}
}
