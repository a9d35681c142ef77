// Helpers shared by the render tests: the MRI volume with a fixed skin TF, and
// an observer that records vtkErrorMacro messages.
#ifndef vsRenderTestUtilities_h
#define vsRenderTestUtilities_h

#include "vtkCommand.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkObject;
class vtkVolumeProperty;

namespace vstest
{
/** The value following `flag` in argv (e.g. "-D"), or "". */
std::string Argument(int argc, char* argv[], const char* flag);

/** Colin27 (ch2.nii.gz) as read by vtkNIFTIImageReader. */
vtkSmartPointer<vtkImageData> ReadBrain(const std::string& path);

/** A fixed skin-and-brain transfer function for ch2 (0..255). */
vtkSmartPointer<vtkVolumeProperty> BrainProperty();

/** Soft assertions of the counter-and-image tests: Check() prints "FAILED: what" to stderr
 *  and counts it; a test returns ExitCode() (EXIT_FAILURE after any failed check). One test
 *  runs per process (ctest), so the count is that test's. */
void Check(bool ok, const std::string& what);
int Failures();
int ExitCode();

/** Records every ErrorEvent/WarningEvent message of the objects it observes. */
class ErrorRecorder : public vtkCommand
{
public:
  static ErrorRecorder* New() { return new ErrorRecorder; }
  void Execute(vtkObject*, unsigned long event, void* data) override;
  void Watch(vtkObject* o);
  bool Saw(const std::string& substring) const;
  std::vector<std::string> Errors, Warnings;
};
}

#endif
