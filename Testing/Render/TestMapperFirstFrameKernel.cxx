// The first frame's render kernel is the one the mapper starts making beside the volume's upload
// (its prewarm), so the first image waits for one pipeline at most: for a thin volume and for one
// whose bricks are optically thick (the trackers' cell walk, a kernel of its own), the first frame
// leaves exactly one new render kernel in the context, the one it ran. Before the prewarm guessed
// the cell walk from the transfer function, the thick volume's first frame made a second kernel
// on the render thread (~0.2 s on lavapipe).
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vsContext.h"
#include "vsRenderTestUtilities.h"

#include "vtkColorTransferFunction.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> RenderKernels()
{
  std::vector<std::string> kernels;
  for (const std::string& name : vs::Context::Default()->PipelineNames())
    if (name.rfind("monte carlo", 0) == 0)
      kernels.push_back(name);
  return kernels;
}
}

int TestMapperFirstFrameKernel(int, char*[])
{
  using vstest::Check;
  for (bool thick : { false, true })
  {
    const std::string what = thick ? "optically thick bricks" : "a thin volume";
    auto image = vstest::Ball(24);
    vtkNew<vtkPiecewiseFunction> opacity;
    opacity->AddPoint(0.0, 0.0);
    opacity->AddPoint(1.0, thick ? 0.95 : 0.02);
    vtkNew<vtkColorTransferFunction> color;
    color->AddRGBPoint(0.0, 1, 1, 1);
    vtkNew<vtkVolumeProperty> property;
    property->SetScalarOpacity(opacity);
    property->SetColor(color);
    // Kernels of their own for each volume (the interpolation is in the name), so that a kernel one
    // volume made cannot hide another's extra one.
    if (thick)
      property->SetInterpolationTypeToNearest();
    else
      property->SetInterpolationTypeToLinear();
    vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
    mapper->SetInputData(image);
    mapper->SetDensityScale(thick ? 30.0 : 1.0);
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkRenderer> renderer;
    renderer->AddVolume(volume);
    vtkNew<vtkRenderWindow> window;
    window->SetSize(32, 32);
    window->AddRenderer(renderer);
    renderer->ResetCamera();

    const std::vector<std::string> before = RenderKernels();
    window->Render();
    const char* error = mapper->GetLastError();
    Check(!error || !*error, what + ": renders (" + std::string(error ? error : "") + ")");
    std::vector<std::string> made;
    for (const std::string& name : RenderKernels())
      if (std::find(before.begin(), before.end(), name) == before.end())
        made.push_back(name);
    Check(made.size() == 1, what + ": the first frame leaves one new render kernel, got " + std::to_string(made.size()));
    for (const std::string& name : made)
      std::printf("%s: %s\n", what.c_str(), name.c_str());
    const bool walks = !made.empty() && made.front().find("cell walk") != std::string::npos;
    Check(walks == thick, what + (thick ? ": its kernel walks the cells of thick bricks" : ": its kernel has no cell walk"));
  }
  return vstest::ExitCode();
}
