// The MRI under a rotated and translated vtkVolume, a parallel projection and a
// clipping plane: the mapper must follow the prop's matrix, the projection and the planes.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

int TestMapperRotatedParallelClipped(int argc, char* argv[])
{
  auto image = vstest::ReadBrain(vstest::Argument(argc, argv, "-D"));
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetRenderModeToEmissionAbsorption();
  vtkNew<vtkPlane> plane;
  double c[3];
  image->GetCenter(c);
  plane->SetOrigin(c);
  plane->SetNormal(-1.0, 0.0, 0.0); // keeps x <= centre (in world space)
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(vstest::BrainProperty());
  volume->SetOrigin(c);
  volume->SetOrientation(0, 0, 35);
  volume->SetPosition(20, 0, 0);
  double pc[3] = { c[0] + 20, c[1], c[2] };
  plane->SetOrigin(pc);
  mapper->AddClippingPlane(plane);

  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  ren->SetBackground(0.0, 0.0, 0.0);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(160, 120);
  ren->GetActiveCamera()->ParallelProjectionOn();
  ren->GetActiveCamera()->SetViewUp(0, 0, 1);
  ren->GetActiveCamera()->SetPosition(pc[0] - 300, pc[1] - 300, pc[2] + 100);
  ren->GetActiveCamera()->SetFocalPoint(pc);
  ren->ResetCamera();
  win->Render();
  if (std::string(mapper->GetLastError()) != "")
  {
    std::cerr << "mapper error: " << mapper->GetLastError() << "\n";
    return EXIT_FAILURE;
  }
  int result = vtkRegressionTestImageThreshold(win, 0.05);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
