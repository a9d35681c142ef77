// Bad input never crashes and never draws: each case reports a vtkErrorMacro
// naming the problem, and the window shows only the background.
#include "vsRenderTestUtilities.h"
#include "vtkVisibilitySweepVolumeMapper.h"

#include "vtkBitArray.h"
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

#include <functional>
#include <iostream>

namespace
{
vtkSmartPointer<vtkImageData> Image(int nx, int ny, int nz, int components = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(nx, ny, nz);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(vtkIdType(nx) * ny * nz);
  a->Fill(1.0);
  image->GetPointData()->SetScalars(a);
  return image;
}

// Renders `image` with `property` and checks for an error containing `expected` and a clean background.
bool Case(const char* name, vtkImageData* image, vtkVolumeProperty* property, const std::string& expected)
{
  vtkNew<vtkVisibilitySweepVolumeMapper> mapper;
  mapper->SetInputData(image);
  vtkNew<vstest::ErrorRecorder> recorder;
  recorder->Watch(mapper);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  ren->SetBackground(0.2, 0.4, 0.6);
  vtkNew<vtkRenderWindow> win;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  win->SetSize(32, 32);
  ren->ResetCamera();
  win->Render();
  win->Render(); // a second render must not crash either
  bool ok = recorder->Saw(expected);
  if (!ok)
  {
    std::cerr << name << ": expected an error containing '" << expected << "', got:";
    for (const auto& e : recorder->Errors)
      std::cerr << " [" << e << "]";
    std::cerr << "\n";
  }
  vtkNew<vtkUnsignedCharArray> pixels;
  win->GetPixelData(0, 0, 31, 31, 0, pixels);
  for (vtkIdType i = 0; i < 32 * 32; ++i)
  {
    if (pixels->GetValue(3 * i) != 51 || pixels->GetValue(3 * i + 1) != 102 || pixels->GetValue(3 * i + 2) != 153)
    {
      std::cerr << name << ": something was drawn\n";
      return false;
    }
  }
  std::cout << name << ": " << (recorder->Errors.empty() ? "" : recorder->Errors.front()) << "\n";
  return ok;
}
}

int TestMapperBadInput(int, char*[])
{
  auto good = vstest::BrainProperty();
  bool ok = true;

  auto noScalars = vtkSmartPointer<vtkImageData>::New();
  noScalars->SetDimensions(8, 8, 8);
  ok &= Case("no scalars", noScalars, good, "no point scalars");

  ok &= Case("three components", Image(8, 8, 8, 3), good, "3 components");

  auto empty = vtkSmartPointer<vtkImageData>::New();
  empty->SetExtent(0, -1, 0, -1, 0, -1);
  ok &= Case("empty extent", empty, good, "empty extent");

  auto bits = vtkSmartPointer<vtkImageData>::New();
  bits->SetDimensions(8, 8, 8);
  vtkNew<vtkBitArray> bitArray;
  bitArray->SetNumberOfTuples(512);
  bits->GetPointData()->SetScalars(bitArray);
  ok &= Case("bit scalars", bits, good, "unsupported type");

  vtkNew<vtkVolumeProperty> noPoints;
  vtkNew<vtkPiecewiseFunction> emptyOpacity;
  noPoints->SetScalarOpacity(emptyOpacity);
  ok &= Case("empty transfer function", Image(8, 8, 8), noPoints, "no points");

  // One voxel more than the device's largest 3D image: refused before any allocation.
  ok &= Case("too large for the device", Image(4097, 2, 2), good, "maxImageDimension3D");

  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
