// A homogeneous cube through the whole VTK path (image data, property, camera,
// window): the pixel at the centre is c * (1 - exp(-sigma_t L)) over black,
// with sigma_t = -ln(1 - alpha) / unitDistance; asserted within 1%.
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <iostream>

int TestMapperCubeAnalytic(int, char*[])
{
  const int n = 21;
  const double spacing = 0.5, alpha = 0.2, unit = 2.0;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->SetSpacing(spacing, spacing, spacing);
  image->SetOrigin(-5.0, -5.0, -5.0);
  vtkNew<vtkFloatArray> values;
  values->SetName("density");
  values->SetNumberOfTuples(n * n * n);
  values->Fill(1.0);
  image->GetPointData()->SetScalars(values);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, alpha);
  opacity->AddPoint(2.0, alpha);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 0.6, 0.3);
  color->AddRGBPoint(2.0, 1.0, 0.6, 0.3);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(unit);

  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(image);
  mapper->SetRenderModeToEmissionAbsorption();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  ren->SetBackground(0, 0, 0);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(64, 64);
  vtkCamera* cam = ren->GetActiveCamera();
  cam->SetPosition(0, 0, 40);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(20);
  ren->ResetCameraClippingRange();
  win->Render();

  vtkNew<vtkUnsignedCharArray> pixels;
  win->GetPixelData(0, 0, 63, 63, 0, pixels);
  const double L = (n - 1) * spacing;
  const double expectedAlpha = 1.0 - std::exp(std::log(1.0 - alpha) / unit * L);
  const double rgb[3] = { 1.0, 0.6, 0.3 };
  int failures = 0;
  for (int y = 30; y <= 33; ++y)
  {
    for (int x = 30; x <= 33; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        double got = pixels->GetValue(3 * (y * 64 + x) + c) / 255.0;
        double want = rgb[c] * expectedAlpha;
        // 1% of the value, plus one 8-bit quantisation step of the window.
        if (std::abs(got - want) > 0.01 * want + 1.0 / 255.0)
        {
          std::cerr << "pixel " << x << "," << y << " channel " << c << ": " << got << " expected " << want << "\n";
          ++failures;
        }
      }
    }
  }
  // A corner pixel sees only the black background.
  if (pixels->GetValue(0) != 0 || pixels->GetValue(1) != 0 || pixels->GetValue(2) != 0)
  {
    std::cerr << "background pixel is not black\n";
    ++failures;
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
