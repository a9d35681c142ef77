// Helpers shared by the render tests: the MRI volume with a fixed skin TF, the synthetic
// volumes, and an observer that records vtkErrorMacro messages.
#ifndef vsRenderTestUtilities_h
#define vsRenderTestUtilities_h

#include "vtkCommand.h"
#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkEnvironmentMapReader;
class vtkImageData;
class vtkObject;
class vtkRenderWindow;
class vtkVolumeProperty;

namespace vstest
{
/** The value following `flag` in argv (e.g. "-D"), or "". */
std::string Argument(int argc, char* argv[], const char* flag);

/** Colin27 (ch2.nii.gz) as read by vtkNIFTIImageReader. */
vtkSmartPointer<vtkImageData> ReadBrain(const std::string& path);

/** Colin27 shrunk `factor` times per axis (averaging), updated so that ResetCamera sees its bounds. */
vtkSmartPointer<vtkImageData> ShrunkBrain(const std::string& path, int factor);

/** The CC0 sunrise HDRI (Data/envmaps) converted at 128^2: the MRI tests' environment. */
vtkSmartPointer<vtkEnvironmentMapReader> SunriseEnvironment();

/** A fixed skin-and-brain transfer function for ch2 (0..255). */
vtkSmartPointer<vtkVolumeProperty> BrainProperty();

/** An n x n x n volume (unit spacing, origin 0) of float point scalars value(x, y, z). */
vtkSmartPointer<vtkImageData> FloatVolume(int n, const std::function<float(int x, int y, int z)>& value);

/** The tests' ball: 1 - r / c at distance r from the centre (c, c, c), c = (n - 1) / 2, and 0 beyond c. */
vtkSmartPointer<vtkImageData> Ball(int n);

/** The window's RGB pixels (rows bottom-up, 3 ints per pixel) as vtkWindowToImageFilter reads them
 *  from the back buffer: as drawn (scale 1, no re-render) or as a tiled screenshot of `scale`. */
std::vector<int> WindowPixels(vtkRenderWindow* win, int scale = 1);

/** Mean |a - b| over the values of two pixel lists, 1e9 when their sizes differ or they are empty. */
double MeanAbsoluteDifference(const std::vector<int>& a, const std::vector<int>& b);
/** Largest |a - b| over the values of two pixel lists, 1e9 when their sizes differ or they are empty. */
int MaxAbsoluteDifference(const std::vector<int>& a, const std::vector<int>& b);

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
