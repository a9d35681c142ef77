// Embedding VisSweep in a C++ VTK application: the Colin27 MRI under an HDR environment
// in an interactive window that keeps refining (progressive Monte Carlo) while the view
// is still, and drops to fast low-resolution frames while the user drags.
//
//   build/bin/vissweep_render_brain [ch2.nii.gz] [environment.exr]
#include "vtkVisibilitySweepVolumeMapper.h"
#include "vtkEnvironmentMapReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkNIFTIImageReader.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

int main(int argc, char* argv[])
{
  const char* volumePath = argc > 1 ? argv[1] : "/usr/share/mricron/templates/ch2.nii.gz";
  const char* environmentPath = argc > 2 ? argv[2] : VISSWEEP_DATA "/envmaps/sunrise.exr";

  vtkNew<vtkNIFTIImageReader> reader;
  reader->SetFileName(volumePath);
  reader->Update();
  vtkNew<vtkEnvironmentMapReader> light;
  light->SetFileName(environmentPath);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0, 0.0);
  opacity->AddPoint(40, 0.0);
  opacity->AddPoint(80, 0.3);
  opacity->AddPoint(255, 0.6);
  vtkNew<vtkColorTransferFunction> albedo;
  albedo->AddRGBPoint(0, 0.9, 0.7, 0.6);
  albedo->AddRGBPoint(255, 1.0, 0.95, 0.9);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(albedo);
  property->SetInterpolationTypeToLinear(); // smooth for an MRI (VTK defaults to nearest, for label maps)

  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputConnection(reader->GetOutputPort());
  mapper->SetEnvironmentConnection(light->GetOutputPort());
  mapper->SetSamplingStrategyToTwoStep();
  mapper->SetMaximumSamples(1024);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);

  vtkNew<vtkRenderer> renderer;
  renderer->AddVolume(volume);
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(512, 512);
  window->SetMultiSamples(0);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->GetActiveCamera()->SetPosition(0.4, 1.0, 0.25);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0);
  renderer->ResetCamera();

  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  interactor->Initialize();
  // Refine while still: every 30 ms, add samples until the mapper has converged.
  vtkNew<vtkCallbackCommand> refine;
  refine->SetClientData(mapper.Get());
  refine->SetCallback([](vtkObject* caller, unsigned long, void* client, void*) {
    auto* m = static_cast<vtkVisibilitySweepVolumeMapper*>(client);
    auto* iren = static_cast<vtkRenderWindowInteractor*>(caller);
    if (!m->IsConverged() && !*m->GetLastError()) // after an error, only interaction renders again
    {
      iren->GetRenderWindow()->Render();
    }
  });
  interactor->AddObserver(vtkCommand::TimerEvent, refine);
  interactor->CreateRepeatingTimer(30);
  window->Render();
  interactor->Start();
  return 0;
}
