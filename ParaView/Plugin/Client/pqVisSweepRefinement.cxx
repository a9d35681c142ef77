#include "pqVisSweepRefinement.h"

#include "pqActiveObjects.h"
#include "pqRepresentation.h"
#include "pqServer.h"
#include "pqView.h"
#include "vtkLogger.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMRenderViewProxy.h"

#include <QApplication>

#include <string>

pqVisSweepRefinement::pqVisSweepRefinement(QObject* p)
  : Superclass(p)
{
  // A render of the small views VisSweep is used with takes tens of milliseconds or more; 30 ms
  // between them keeps the GUI responsive.
  this->Timer.setInterval(30);
  QObject::connect(&this->Timer, &QTimer::timeout, this, &pqVisSweepRefinement::refine);
}

pqVisSweepRefinement::~pqVisSweepRefinement() = default;

void pqVisSweepRefinement::onStartup()
{
  this->Timer.start();
}

void pqVisSweepRefinement::onShutdown()
{
  this->Timer.stop();
}

void pqVisSweepRefinement::refine()
{
  // Builtin and remote sessions alike: with a pvserver the representation's proxy
  // (vtkSMVisSweepRepresentationProxy) reads Converged and AccumulatedSamples from the server, where
  // the volume renders, and forceRender() asks the server for a still frame.
  pqView* view = pqActiveObjects::instance().activeView();
  if (!view || !vtkSMRenderViewProxy::SafeDownCast(view->getProxy()) ||
    QApplication::mouseButtons() != Qt::NoButton)
  {
    return;
  }
  bool refining = false;
  int samples = -1;
  for (pqRepresentation* repr : view->getRepresentations())
  {
    vtkSMProxy* proxy = repr ? repr->getProxy() : nullptr;
    if (!proxy || !repr->isVisible() || !proxy->GetProperty("Converged") ||
      !proxy->GetProperty("Representation") ||
      std::string(vtkSMPropertyHelper(proxy, "Representation").GetAsString()) != "VisSweep Volume")
    {
      continue;
    }
    proxy->UpdatePropertyInformation();
    const char* error = vtkSMPropertyHelper(proxy, "LastError").GetAsString();
    if (error && *error)
    {
      continue; // the error is in the output window; do not render it again and again
    }
    samples = vtkSMPropertyHelper(proxy, "AccumulatedSamples").GetAsInt();
    if (vtkSMPropertyHelper(proxy, "Converged").GetAsInt() == 0)
    {
      refining = true;
    }
  }
  if (refining)
  {
    view->forceRender();
  }
  else if (samples >= 0 && samples != this->LastReported)
  {
    vtkLogF(INFO, "VisSweep: the view is converged at %d samples per pixel (%s session)", samples,
      view->getServer() && view->getServer()->isRemote() ? "remote" : "builtin");
  }
  this->LastReported = refining ? -1 : samples;
}
