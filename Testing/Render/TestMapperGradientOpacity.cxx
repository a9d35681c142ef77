// The vtkVolumeProperty's gradient opacity (issue 14), as vtkGPUVolumeRayCastMapper applies it: opacity x
// gradient-opacity(|grad s|). A ball with a homogeneous core (the tests' Ball, tripled and clamped at 1: s =
// 1 for r < 2c/3, a ramp to 0 at r = c) under a gradient opacity that is 0 where the gradient is 0 renders as
// a hollow shell: the core is transparent. Measured on the image, in the Monte Carlo mode (the Alpha array of
// GetRadiance) and in the emission-absorption mode (the window's pixels): without the gradient opacity the
// centre is the most opaque part of the disc and nearly opaque; with it the centre is clearly translucent and
// less opaque than the rays that graze the core (limb brightening, the signature of a shell). The visibility
// grid sees the hollow core too (more light reaches the centre), a change of the gradient-opacity function
// re-renders, recomputes the majorants and the grid (by MTime, as the scalar opacity does), an unchanged one
// does nothing, and nothing is warned about.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using vstest::Check;

namespace
{
const int kVoxels = 32;
const int kPixels = 48;

// Mean of `value` (one per pixel, rows bottom-up) over the pixels whose distance from the disc's centre is in
// [lo, hi) x its radius; the disc is where `reference` exceeds 0.05.
struct Disc
{
  double X = 0.0, Y = 0.0, Radius = 0.0;
};

Disc FindDisc(const std::vector<double>& reference)
{
  Disc d;
  double n = 0.0;
  for (int y = 0; y < kPixels; ++y)
    for (int x = 0; x < kPixels; ++x)
      if (reference[size_t(y) * kPixels + x] > 0.05)
      {
        d.X += x;
        d.Y += y;
        n += 1.0;
      }
  if (n > 0.0)
  {
    d.X /= n;
    d.Y /= n;
    d.Radius = std::sqrt(n / M_PI);
  }
  return d;
}

double RingMean(const std::vector<double>& value, const Disc& d, double lo, double hi)
{
  double sum = 0.0, n = 0.0;
  for (int y = 0; y < kPixels; ++y)
    for (int x = 0; x < kPixels; ++x)
    {
      const double r = std::hypot(x - d.X, y - d.Y) / std::max(d.Radius, 1e-9);
      if (r >= lo && r < hi)
      {
        sum += value[size_t(y) * kPixels + x];
        n += 1.0;
      }
    }
  return n > 0.0 ? sum / n : -1.0;
}

std::vector<double> Alpha(vtkVisibilitySweepVolumeMapper* m)
{
  std::vector<double> a;
  vtkImageData* r = m->GetRadiance();
  vtkDataArray* alpha = r ? r->GetPointData()->GetArray("Alpha") : nullptr;
  if (alpha)
    for (vtkIdType i = 0; i < alpha->GetNumberOfTuples(); ++i)
      a.push_back(alpha->GetComponent(i, 0));
  return a;
}

std::vector<double> Brightness(vtkRenderWindow* win)
{
  std::vector<int> rgb = vstest::WindowPixels(win);
  std::vector<double> b;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3)
    b.push_back((rgb[i] + rgb[i + 1] + rgb[i + 2]) / (3.0 * 255.0));
  return b;
}

// The mean distance from the ball's centre of the voxels a point selection of the 5 x 5 pixels at the image's
// centre picks (-1 without any).
double PickedRadius(vtkRenderer* ren, vtkVolume* volume, double c)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(ren);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_POINTS);
  selector->SetArea(kPixels / 2 - 2, kPixels / 2 - 2, kPixels / 2 + 2, kPixels / 2 + 2);
  vtkSmartPointer<vtkSelection> picked;
  picked.TakeReference(selector->Select());
  double sum = 0.0, n = 0.0;
  for (unsigned int i = 0; picked && i < picked->GetNumberOfNodes(); ++i)
  {
    vtkSelectionNode* node = picked->GetNode(i);
    auto* list = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    if (node->GetProperties()->Get(vtkSelectionNode::PROP()) != volume || !list)
      continue;
    for (vtkIdType t = 0; t < list->GetNumberOfTuples(); ++t)
    {
      const vtkIdType id = list->GetValue(t);
      const double x = double(id % kVoxels), y = double((id / kVoxels) % kVoxels), z = double(id / (kVoxels * kVoxels));
      sum += std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
      n += 1.0;
    }
  }
  return n > 0.0 ? sum / n : -1.0;
}

double CentreVisibility(vtkVisibilitySweepVolumeMapper* m)
{
  vtkImageData* g = m->GetVisibilityGrid();
  vtkDataArray* mean = g ? g->GetPointData()->GetArray("MeanVisibility") : nullptr;
  if (!mean)
    return -1.0;
  int d[3];
  g->GetDimensions(d);
  return mean->GetComponent((vtkIdType(d[2] / 2) * d[1] + d[1] / 2) * d[0] + d[0] / 2, 0);
}
} // namespace

int TestMapperGradientOpacity(int, char*[])
{
  const double c = 0.5 * (kVoxels - 1);
  auto image = vstest::FloatVolume(kVoxels,
    [c](int x, int y, int z)
    {
      const double r = std::sqrt((x - c) * (x - c) + (y - c) * (y - c) + (z - c) * (z - c));
      return float(std::min(1.0, 3.0 * std::max(0.0, 1.0 - r / c)));
    });
  vtkNew<vtkVisibilitySweepVolumeMapper> m;
  m->SetInputData(image);
  m->SetEnvironmentVisible(false); // alpha is the opacity; the background is black
  m->SetSamplingStrategyToTwoStep();
  m->ProgressiveVisibilityOff(); // the grid swept in the frame that needs it
  m->SetSamplesPerFrame(64);
  m->SetMaximumSamples(64);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(m);

  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(0.0, 0.0);
  opacity->AddPoint(1.0, 0.15);
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  color->AddRGBPoint(1.0, 1.0, 1.0, 1.0);
  // 0 where the scalar is flat (the core, and the empty space outside), 1 on the ramp (|grad s| = 3 / c).
  vtkNew<vtkPiecewiseFunction> gradient;
  gradient->AddPoint(0.0, 0.0);
  gradient->AddPoint(0.02, 0.0);
  gradient->AddPoint(0.05, 1.0);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  property->SetColor(color);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(m);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AddVolume(volume);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->SetSize(kPixels, kPixels);
  win->AddRenderer(ren);
  ren->GetActiveCamera()->ParallelProjectionOn();
  ren->GetActiveCamera()->SetPosition(c, c, 100.0);
  ren->GetActiveCamera()->SetFocalPoint(c, c, c);
  ren->ResetCamera();

  auto render = [&](const std::string& what)
  {
    win->Render();
    Check(std::string(m->GetLastError()).empty(), what + " renders: " + m->GetLastError());
  };

  // Monte Carlo, without and with the gradient opacity.
  render("Monte Carlo without gradient opacity");
  const std::vector<double> plain = Alpha(m);
  const double plainVisibility = CentreVisibility(m);
  property->SetGradientOpacity(gradient);
  const int majorants = m->GetMajorantUpdateCount(), sweeps = m->GetVisibilityUpdateCount(),
            resets = m->GetAccumulationResetCount();
  render("Monte Carlo with gradient opacity");
  const std::vector<double> shell = Alpha(m);
  const double shellVisibility = CentreVisibility(m);
  Check(m->GetMajorantUpdateCount() == majorants + 1, "a gradient opacity recomputes the majorants");
  Check(m->GetVisibilityUpdateCount() == sweeps + 1, "a gradient opacity recomputes the visibility grid");
  Check(m->GetAccumulationResetCount() == resets + 1, "a gradient opacity restarts accumulation");
  Check(plain.size() == size_t(kPixels * kPixels) && shell.size() == plain.size(), "both renders have alpha");
  if (plain.size() != shell.size() || plain.empty())
    return vstest::ExitCode();
  const Disc disc = FindDisc(plain);
  const double plainCentre = RingMean(plain, disc, 0.0, 0.25), plainRim = RingMean(plain, disc, 0.6, 0.75);
  const double shellCentre = RingMean(shell, disc, 0.0, 0.25), shellRim = RingMean(shell, disc, 0.6, 0.75);
  std::cout << "disc radius " << disc.Radius << " px; Monte Carlo alpha: centre " << plainCentre << " -> "
            << shellCentre << ", rim " << plainRim << " -> " << shellRim << "; centre mean visibility "
            << plainVisibility << " -> " << shellVisibility << "\n";
  Check(disc.Radius > 0.25 * kPixels, "the ball fills the view");
  Check(plainCentre > 0.95, "without gradient opacity the core is nearly opaque");
  Check(plainCentre > plainRim, "without gradient opacity the centre is the most opaque");
  Check(shellCentre < 0.75, "with gradient opacity the core is transparent: only the shell absorbs");
  Check(shellCentre < plainCentre - 0.2, "the gradient opacity removes the core's opacity");
  Check(shellRim > shellCentre + 0.05, "with gradient opacity rays grazing the core see more (a hollow shell)");
  Check(shellVisibility > plainVisibility + 0.05, "the visibility grid sees the hollow core");

  // Unchanged: nothing is redone; a new point of the function (its MTime) redoes it all.
  const int after = m->GetMajorantUpdateCount();
  const int sweptAfter = m->GetVisibilityUpdateCount(), resetAfter = m->GetAccumulationResetCount();
  render("an unchanged gradient opacity");
  Check(m->GetAccumulationResetCount() == resetAfter, "an unchanged gradient opacity keeps accumulating");
  Check(m->GetMajorantUpdateCount() == after, "an unchanged gradient opacity keeps the majorants");
  gradient->AddPoint(0.2, 0.5);
  render("a modified gradient opacity");
  Check(m->GetMajorantUpdateCount() == after + 1, "a modified gradient-opacity function recomputes the majorants");
  Check(m->GetVisibilityUpdateCount() == sweptAfter + 1, "a modified gradient-opacity function re-sweeps");
  Check(m->GetAccumulationResetCount() == resetAfter + 1, "a modified gradient-opacity function restarts");
  gradient->RemovePoint(0.2);

  // Emission-absorption: the same hollow shell in the window's pixels.
  m->SetRenderModeToEmissionAbsorption();
  property->DisableGradientOpacityOn();
  render("emission-absorption without gradient opacity");
  const std::vector<double> eaPlain = Brightness(win);
  property->DisableGradientOpacityOff();
  render("emission-absorption with gradient opacity");
  const std::vector<double> eaShell = Brightness(win);
  Check(eaPlain.size() == size_t(kPixels * kPixels) && eaShell.size() == eaPlain.size(), "both have pixels");
  if (eaPlain.size() == eaShell.size() && !eaPlain.empty())
  {
    const double pc = RingMean(eaPlain, disc, 0.0, 0.25), pr = RingMean(eaPlain, disc, 0.6, 0.75);
    const double sc = RingMean(eaShell, disc, 0.0, 0.25), sr = RingMean(eaShell, disc, 0.6, 0.75);
    std::cout << "emission-absorption brightness: centre " << pc << " -> " << sc << ", rim " << pr << " -> " << sr
              << "\n";
    Check(pc > pr,
      "emission-absorption without gradient opacity: the centre "
      "is the brightest");
    Check(sc < pc - 0.2,
      "emission-absorption honours the gradient opacity: "
      "the core is transparent");
    Check(sr > sc + 0.05, "emission-absorption with gradient opacity: a hollow shell");
  }
  // Picking marches the same extinction: a gradient opacity that keeps only the flat core (1 where the
  // gradient is 0, 0 on the ramp) moves the picked voxels from the ball's surface (r = c) to the core's (r =
  // 2c/3).
  property->DisableGradientOpacityOn();
  const double surface = PickedRadius(ren, volume, c);
  vtkNew<vtkPiecewiseFunction> core;
  core->AddPoint(0.0, 1.0);
  core->AddPoint(0.02, 1.0);
  core->AddPoint(0.05, 0.0);
  property->SetGradientOpacity(core);
  property->DisableGradientOpacityOff();
  const double coreSurface = PickedRadius(ren, volume, c);
  std::cout << "picked radius " << surface << " -> " << coreSurface << " (ball " << c << ", core " << 2.0 * c / 3.0
            << ")\n";
  Check(std::abs(surface - c) < 1.5, "without gradient opacity the pick is at the ball's surface");
  Check(std::abs(coreSurface - 2.0 * c / 3.0) < 1.5, "with the core's gradient opacity the pick is at the core");
  Check(std::string(m->GetLastError()).empty(), std::string("picking renders: ") + m->GetLastError());

  Check(std::none_of(recorder->Warnings.begin(), recorder->Warnings.end(),
          [](const std::string& w) { return w.find("gradient") != std::string::npos; }),
    "the gradient opacity is honoured: no warning");
  Check(recorder->Errors.empty(), "no errors");
  return vstest::ExitCode();
}
