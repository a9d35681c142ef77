// vsFuzzVTK.h — VTK helpers of the reader fuzz targets.
#ifndef vsFuzzVTK_h
#define vsFuzzVTK_h

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkLogger.h"
#include "vtkNew.h"
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

/* Counts the ErrorEvents of an algorithm and of its executive (the pipeline reports
 * RequestData failures there). */
class ErrorCount
{
public:
  ErrorCount()
  {
    this->Observer->SetCallback(&ErrorCount::Increment);
    this->Observer->SetClientData(&this->Count);
  }
  void Watch(vtkAlgorithm* algorithm)
  {
    algorithm->AddObserver(vtkCommand::ErrorEvent, this->Observer);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->Observer);
  }
  int Count = 0;

private:
  static void Increment(vtkObject*, unsigned long, void* count, void*) { ++*static_cast<int*>(count); }
  vtkNew<vtkCallbackCommand> Observer;
};

}

#endif
