// VTK's cropping region flags other than the subvolume (issue 14): the visible set is a union of
// the 27 regions the cropping planes make, honoured in the Monte Carlo render (with the sweeps:
// TwoStep), the emission-absorption mode and the projections. A dense cube of 24^3 voxels with the
// planes at 8 and 16 on every axis and the regions {rz = 1 and (rx = 1 or ry = 1)} (a plus sign in
// the middle slab) and (0, 0, 0) (a corner) visible, seen along -z and along -x with parallel
// cameras: a pixel's ray is empty exactly when every region it crosses is hidden, so its alpha is 0
// (Monte Carlo: exactly, no collision) or the medium shows (alpha near 1), pixel by pixel against
// the region pattern (pixels within a voxel of a plane or the box edge are not judged).
// VTK's named flags (VTK_CROP_FENCE, ...) render without an error.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

using vstest::Check;

namespace
{
const int N = 24, W = 40, H = 40;
const double Scale = 14.0; // parallel scale: the view's half height in world units

int Region(double v)
{
  return (v >= 8.0) + (v >= 16.0);
}

// Distance of v from the region boundaries and the box faces.
double Margin(double v)
{
  return std::min({ std::abs(v - 0.0), std::abs(v - 8.0), std::abs(v - 16.0), std::abs(v - 23.0) });
}

bool Visible(int rx, int ry, int rz)
{
  return (rz == 1 && (rx == 1 || ry == 1)) || (rx == 0 && ry == 0 && rz == 0);
}

int Flags()
{
  int flags = 0;
  for (int r = 0; r < 27; ++r)
  {
    flags |= Visible(r % 3, (r / 3) % 3, r / 9) ? 1 << r : 0;
  }
  return flags;
}
}

int TestMapperCroppingRegions(int, char*[])
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(N, N, N);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfTuples(N * N * N);
  a->Fill(1.0);
  image->GetPointData()->SetScalars(a);

  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(image);
  m->SetEnvironmentVisible(false);
  m->SetSamplingStrategyToTwoStep();
  m->ProgressiveVisibilityOff();
  m->SetSamplesPerFrame(4);
  m->SetMaximumSamples(4);
  m->CroppingOn();
  m->SetCroppingRegionPlanes(8.0, 16.0, 8.0, 16.0, 8.0, 16.0);
  m->SetCroppingRegionFlags(Flags());
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.95);
  opacity->AddPoint(1.0, 0.95);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetScalarOpacityUnitDistance(0.25);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(W, H);
  win->AddRenderer(ren);
  vtkCamera* camera = ren->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(Scale);
  camera->SetClippingRange(1.0, 1000.0);

  // Two views: along -z (pixel (i, j) at world (x, y)) and along -x (pixel at world (y, z)).
  struct View
  {
    const char* Name;
    double Position[3], Up[3];
    std::function<bool(double, double)> Lit; // whether the ray through (u, v) crosses a visible region
  };
  const double c = 0.5 * (N - 1);
  const View views[] = {
    { "along -z", { c, c, 200.0 }, { 0, 1, 0 },
      [](double x, double y) {
        return Visible(Region(x), Region(y), 0) || Visible(Region(x), Region(y), 1) ||
          Visible(Region(x), Region(y), 2);
      } },
    { "along -x", { 200.0, c, c }, { 0, 0, 1 },
      [](double u, double z) {
        return Visible(0, Region(u), Region(z)) || Visible(1, Region(u), Region(z)) || Visible(2, Region(u), Region(z));
      } },
  };
  for (const View& view : views)
  {
    camera->SetFocalPoint(c, c, c);
    camera->SetPosition(view.Position);
    camera->SetViewUp(view.Up);
    for (int mode : { int(vtkVisibilitySweepVolumeMapper::MonteCarlo), int(vtkVisibilitySweepVolumeMapper::EmissionAbsorption),
           -1 })
    {
      m->SetBlendMode(mode < 0 ? vtkVolumeMapper::MAXIMUM_INTENSITY_BLEND : vtkVolumeMapper::COMPOSITE_BLEND);
      m->SetRenderMode(mode < 0 ? int(vtkVisibilitySweepVolumeMapper::MonteCarlo) : mode);
      const std::string what = std::string(view.Name) +
        (mode < 0 ? ", MIP" : mode == vtkVisibilitySweepVolumeMapper::MonteCarlo ? ", Monte Carlo" : ", emission-absorption");
      win->Render();
      Check(std::string(m->GetLastError()).empty(), what + " renders: " + m->GetLastError());
      vtkDataArray* alpha = nullptr;
      vtkNew<vtkWindowToImageFilter> grab;
      if (mode == vtkVisibilitySweepVolumeMapper::MonteCarlo)
      {
        vtkImageData* r = m->GetRadiance();
        alpha = r ? r->GetPointData()->GetArray("Alpha") : nullptr;
      }
      else
      {
        grab->SetInput(win);
        grab->ShouldRerenderOff();
        grab->Update();
        alpha = grab->GetOutput()->GetPointData()->GetScalars();
      }
      if (!alpha || alpha->GetNumberOfTuples() != W * H)
      {
        Check(false, what + ": an image of the window's size");
        continue;
      }
      const double full = mode == vtkVisibilitySweepVolumeMapper::MonteCarlo ? 1.0 : 255.0;
      int judged = 0, lit = 0, wrong = 0;
      for (int j = 0; j < H; ++j)
        for (int i = 0; i < W; ++i)
        {
          const double su = ((i + 0.5) / W * 2.0 - 1.0) * Scale * double(W) / H;
          const double sv = ((j + 0.5) / H * 2.0 - 1.0) * Scale;
          const double u = c + su, v = c + sv; // screen right is +x (along -z) or +y (along -x)
          if (Margin(u) < 1.0 || Margin(v) < 1.0 || u < 0.0 || u > N - 1 || v < 0.0 || v > N - 1)
          {
            continue;
          }
          ++judged;
          // Monte Carlo: alpha itself; the window: its red channel (white medium over black).
          const double value = alpha->GetComponent(i + j * W, 0) / full;
          const bool expected = view.Lit(u, v);
          lit += expected;
          const bool ok = expected ? value > 0.5 : value == 0.0;
          if (!ok && wrong++ < 5)
          {
            Check(false, what + ": pixel (" + std::to_string(i) + ", " + std::to_string(j) + ") at (" +
                std::to_string(u) + ", " + std::to_string(v) + ") reads " + std::to_string(value) +
                (expected ? ", expected the medium" : ", expected nothing"));
          }
        }
      std::cout << what << ": " << judged << " pixels judged, " << lit << " lit, " << wrong << " wrong\n";
      Check(judged > 400 && lit > 100 && judged - lit > 100, what + ": both kinds of pixels judged");
      Check(wrong == 0, what + ": every pixel as the regions say");
    }
  }
  m->SetBlendModeToComposite();
  Check(m->GetVisibilityUpdateCount() >= 1, "the sweeps ran under the cropping regions");

  // VTK's named flags render (no error).
  for (int flags : { VTK_CROP_FENCE, VTK_CROP_INVERTED_FENCE, VTK_CROP_CROSS, VTK_CROP_INVERTED_CROSS })
  {
    m->SetCroppingRegionFlags(flags);
    win->Render();
    Check(std::string(m->GetLastError()).empty(), "flags " + std::to_string(flags) + " render: " + m->GetLastError());
  }
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
