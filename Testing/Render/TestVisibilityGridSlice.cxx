// The MeanVisibility (1 - ambient occlusion) of the MRI's visibility grid, a slice through
// the middle shown with a grey colour map: an image regression of vtkVisibilityGridFilter
// used as an ordinary VTK pipeline stage.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilityGridFilter.h"

#include "vtkCamera.h"
#include "vtkExtractVOI.h"
#include "vtkImageActor.h"
#include "vtkImageData.h"
#include "vtkImageMapToColors.h"
#include "vtkImageMapper3D.h"
#include "vtkImageShrink3D.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolumeProperty.h"

int TestVisibilityGridSlice(int argc, char* argv[])
{
  auto brain = vstest::ReadBrain(vstest::Argument(argc, argv, "-D"));
  vtkNew<vtkImageShrink3D> shrink;
  shrink->SetInputData(brain);
  shrink->SetShrinkFactors(2, 2, 2);
  vtkNew<vtkVisibilityGridFilter> grid;
  grid->SetInputConnection(shrink->GetOutputPort());
  grid->SetVolumeProperty(vstest::BrainProperty());
  grid->SetVoxelsPerCell(2);
  grid->Update();
  int dims[3];
  grid->GetOutput()->GetDimensions(dims);
  vtkNew<vtkExtractVOI> slice;
  slice->SetInputConnection(grid->GetOutputPort());
  slice->SetVOI(0, dims[0] - 1, 0, dims[1] - 1, dims[2] / 2, dims[2] / 2);
  vtkNew<vtkLookupTable> grey;
  grey->SetRange(0.0, 1.0);
  grey->SetSaturationRange(0, 0);
  grey->SetValueRange(0, 1);
  grey->Build();
  vtkNew<vtkImageMapToColors> colors;
  colors->SetInputConnection(slice->GetOutputPort());
  colors->SetLookupTable(grey);
  colors->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "MeanVisibility");
  vtkNew<vtkImageActor> actor;
  actor->GetMapper()->SetInputConnection(colors->GetOutputPort());
  actor->InterpolateOff();
  vtkNew<vtkRenderer> ren;
  ren->AddActor(actor);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(128, 128);
  ren->ResetCamera();
  win->Render();
  int result = vtkRegressionTestImageThreshold(win, 0.05);
  return result == vtkRegressionTester::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
