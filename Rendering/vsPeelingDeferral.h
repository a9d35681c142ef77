// vsPeelingDeferral.h — VisSweep under VTK's depth peeling for volumes. With UseDepthPeeling and
// UseDepthPeelingForVolumes on and translucent geometry in the scene, vtkDualDepthPeelingPass draws
// the volumes itself, several times a frame, into its own peeling framebuffer (viewport at the
// origin, MAX blending): the composited Monte Carlo image came out striped and corrupt (issue 14).
// VisSweep cannot interleave its volume with the peels (the peel depths are the pass's private
// textures), so a volume asked to draw inside the peeling pass draws nothing there and draws once
// at the end of the renderer's frame (its EndEvent) instead, over the peeled translucent geometry:
// the image of UseDepthPeelingForVolumes off (except that 2D overlays are then under the volume).
#ifndef vsPeelingDeferral_h
#define vsPeelingDeferral_h

#include "vtkRenderer.h"
#include "vtkWeakPointer.h"

#include <functional>

class vtkObject;
class vtkVolume;

namespace vs
{
class PeelingDeferral
{
public:
  PeelingDeferral() = default;
  ~PeelingDeferral();
  PeelingDeferral(const PeelingDeferral&) = delete;
  PeelingDeferral& operator=(const PeelingDeferral&) = delete;

  /** Whether `vol` is being drawn by a vtkDualDepthPeelingPass (its property keys hold the pass). */
  static bool InsidePeeling(vtkVolume* vol);

  /** Calls `draw` once at the end of `ren`'s current frame, however often it is deferred in that
   *  frame. Nothing is called after this object is destroyed. */
  void Defer(vtkRenderer* ren, std::function<void()> draw);

  /** Draws deferred so far (for tests and PrintSelf). */
  int Deferred() const { return this->Count; }

private:
  static void OnEnd(vtkObject* caller, unsigned long event, void* self, void*);
  void Cancel();
  vtkWeakPointer<vtkRenderer> Pending;
  unsigned long Tag = 0;
  std::function<void()> Draw;
  int Count = 0;
};
}

#endif
