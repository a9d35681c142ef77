// The MRI (Colin27, halved to keep CI fast) by Monte Carlo single scattering under a
// real HDRI (sunrise) with the TwoStep strategy, fixed seed and samples; with "-clip",
// a clipping plane opens the head. Regression images.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkEnvironmentMapReader.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkPlane.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>

int RenderMonteCarloBrain(int argc, char* argv[], bool clip)
{
  auto brain = vstest::ShrunkBrain(vstest::Argument(argc, argv, "-D"), 2);
  auto env = vstest::SunriseEnvironment();
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(brain);
  mapper->SetEnvironmentConnection(env->GetOutputPort());
  mapper->SetSamplingStrategyToTwoStep();
  mapper->SetSeed(3);
  mapper->SetSamplesPerFrame(8);
  mapper->SetMaximumSamples(16);
  if (clip)
  {
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(90, 108, 90);
    plane->SetNormal(-1, 0, 0);
    mapper->AddClippingPlane(plane);
  }
  auto property = vstest::BrainProperty();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(96, 96);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetViewUp(0, 0, 1);
  cam->SetFocalPoint(90, 108, 90);
  cam->SetPosition(90 + 300, 108 + 420, 90 + 120);
  ren->ResetCamera();
  for (int i = 0; i < 3 && !mapper->IsConverged(); ++i)
  {
    win->Render();
  }
  if (std::string(mapper->GetLastError()) != "" || mapper->GetAccumulatedSamples() != 16)
  {
    std::cerr << "mapper error: '" << mapper->GetLastError() << "', samples " << mapper->GetAccumulatedSamples() << "\n";
    return EXIT_FAILURE;
  }
  // The radiance is finite and not blank.
  vtkImageData* radiance = mapper->GetRadiance();
  double sum = 0.0;
  for (vtkIdType i = 0; i < radiance->GetNumberOfPoints(); ++i)
  {
    double* v = radiance->GetPointData()->GetScalars()->GetTuple3(i);
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
    {
      std::cerr << "non-finite radiance at pixel " << i << "\n";
      return EXIT_FAILURE;
    }
    sum += v[0] + v[1] + v[2];
  }
  if (!(sum > 0.0))
  {
    std::cerr << "blank radiance\n";
    return EXIT_FAILURE;
  }
  int result = vtkRegressionTestImageThreshold(win, 0.05);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}

int TestMapperMonteCarloBrain(int argc, char* argv[])
{
  return RenderMonteCarloBrain(argc, argv, false);
}
