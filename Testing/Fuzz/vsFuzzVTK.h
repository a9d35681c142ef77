// vsFuzzVTK.h — VTK helpers of the reader fuzz targets.
#ifndef vsFuzzVTK_h
#define vsFuzzVTK_h

#include "vtkLogger.h"
#include "vtkOutputWindow.h"

namespace vsfuzz
{
/* Keeps VTK's messages off stderr (most inputs are errors): messages of objects with an
 * ErrorEvent observer go to the observer; the rest would go to the output window. */
class SilentOutputWindow : public vtkOutputWindow
{
public:
  static SilentOutputWindow* New()
  {
    auto* w = new SilentOutputWindow;
    w->InitializeObjectBase();
    return w;
  }
  void DisplayText(const char*) override {}
};

inline void SilenceVTK()
{
  auto* w = SilentOutputWindow::New();
  vtkOutputWindow::SetInstance(w);
  w->Delete();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

}

#endif
