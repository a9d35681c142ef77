// vsPropertyChecks.h — the vtkVolumeProperty, mapper and renderer settings VisSweep does not
// honour, said once per change. VTK users set these for vtkGPUVolumeRayCastMapper; silently
// ignoring them shows a different picture without a word. The mapper asks Ignored() each
// Render() and logs only what is new (NewWarnings), so a render loop does not flood the log.
// (Errors are logged once per change by the mapper's ReportError.)
#ifndef vsPropertyChecks_h
#define vsPropertyChecks_h

#include "vtkRenderer.h"
#include "vtkWeakPointer.h"

#include <string>
#include <utility>
#include <vector>

class vtkVolumeMapper;
class vtkVolumeProperty;

namespace vs
{
class PropertyChecks
{
public:
  /** The settings the next render ignores, one sentence each (empty: all honoured).
   *  monteCarlo: the Monte Carlo light transport renders (composite blend in Monte Carlo mode);
   *  projection: a projection blend mode (MIP, MinIP, average, additive) renders. */
  static std::vector<std::string> Ignored(vtkVolumeMapper* mapper, vtkVolumeProperty* property,
    vtkRenderer* renderer, bool monteCarlo, bool projection);

  /** VTK's cropping region flags in words ("VTK_CROP_FENCE", ...; other values in hex). */
  static std::string CroppingFlagsName(int flags);

  /** The warnings of `current` that were not in the previous call's for the same renderer: a
   *  setting warns when it becomes ignored (or changes) in a view, not again while it stays so.
   *  Per renderer, since some settings are (depth peeling on in one of two views warned on every
   *  frame when one list was kept for both); renderers that are gone are forgotten. */
  std::vector<std::string> NewWarnings(vtkRenderer* renderer, const std::vector<std::string>& current);

private:
  std::vector<std::pair<vtkWeakPointer<vtkRenderer>, std::vector<std::string>>> Active;
};
}

#endif
