// The MRI (Colin27) by emission-absorption, with an opaque sphere inside it:
// the volume must composite over the sphere (rays stop at its depth).
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

int TestMapperBrainEmissionAbsorption(int argc, char* argv[])
{
  auto image = vstest::ReadBrain(vstest::Argument(argc, argv, "-D"));
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetSeed(7);
  mapper->SetRenderModeToEmissionAbsorption();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(vstest::BrainProperty());

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(image->GetCenter());
  sphere->SetRadius(40);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(sphereMapper);
  actor->GetProperty()->SetColor(0.2, 0.8, 0.2);

  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  ren->AddActor(actor);
  ren->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(160, 160);
  ren->ResetCamera();
  ren->GetActiveCamera()->Azimuth(30);
  ren->GetActiveCamera()->Elevation(20);
  win->Render();
  if (std::string(mapper->GetLastError()) != "")
  {
    std::cerr << "mapper error: " << mapper->GetLastError() << "\n";
    return EXIT_FAILURE;
  }
  int result = vtkRegressionTestImageThreshold(win, 0.05);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
