// libFuzzer target: vtkEnvironmentMapReader (OpenEXR through the OpenEXR library, Radiance
// .hdr through vtkHDRReader; the reader recognises the format by content). The input bytes
// are written to a scratch file and read. Contract under test (vtkEnvironmentMapReader.h):
// the read ends either in an error (vtkErrorMacro, empty output) or in a valid octahedral map
// (N x N x 1, N a power of two, "Radiance" and "Importance" finite and non-negative) — never
// a crash, a sanitizer report or an unbounded allocation.
//
// Harness limits (documented in docs/benchmarks.md): MaximumNumberOfPixels is lowered to 64
// (the seeds are 8 x 4) and the octahedral size fixed at 16, so that one input reads and
// converts in milliseconds: a source wider than the map is converted at DefaultSize(width, height)
// first, seconds for a 64K-pixel-wide image under ASan. The limit path itself is under test.
#include "vtkEnvironmentMapReader.h"

#include "vsFuzzUtilities.h"
#include "vsFuzzVTK.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <string>

namespace
{
constexpr vtkIdType MaxPixels = 64;

void CheckArray(vtkDataArray* a, const char* name, vtkIdType tuples, int components)
{
  if (!a)
  {
    vsfuzz::Fail(std::string("no point array ") + name + " in a successful read");
  }
  if (a->GetNumberOfTuples() != tuples || a->GetNumberOfComponents() != components)
  {
    vsfuzz::Fail(std::string("point array ") + name + " has the wrong size");
  }
  for (vtkIdType i = 0; i < tuples; ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      const double v = a->GetComponent(i, c);
      if (!std::isfinite(v) || v < 0.0)
      {
        vsfuzz::Fail(std::string(name) + " value " + std::to_string(v) + " at texel " +
          std::to_string(i) + " is not finite and non-negative");
      }
    }
  }
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vsfuzz::SilenceVTK(); // errors are expected for most inputs; observers count them
  vtkSMPTools::Initialize(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string& path = vsfuzz::ScratchFile(".exr");
  vsfuzz::WriteFile(path, data, size);

  vsfuzz::ErrorCount errors;

  vtkNew<vtkEnvironmentMapReader> reader;
  errors.Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetMaximumNumberOfPixels(MaxPixels);
  reader->SetOctahedralSize(16);
  reader->Update();

  vtkImageData* out = reader->GetOutput();
  const vtkIdType points = out->GetNumberOfPoints();
  if (errors.Count > 0)
  {
    if (points != 0)
    {
      vsfuzz::Fail("an error was reported but the output has " + std::to_string(points) + " points");
    }
    return 0;
  }
  int dims[3];
  out->GetDimensions(dims);
  if (dims[0] != 16 || dims[1] != 16 || dims[2] != 1)
  {
    vsfuzz::Fail("no error, but the output is " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) +
      " x " + std::to_string(dims[2]) + ", not 16 x 16 x 1");
  }
  CheckArray(out->GetPointData()->GetArray("Radiance"), "Radiance", points, 3);
  CheckArray(out->GetPointData()->GetArray("Importance"), "Importance", points, 1);
  if (!std::isfinite(reader->GetTotalPower()) || reader->GetTotalPower() < 0.0)
  {
    vsfuzz::Fail("TotalPower " + std::to_string(reader->GetTotalPower()) + " is not finite and non-negative");
  }
  if (reader->GetLatLongWidth() <= 0 || reader->GetLatLongHeight() <= 0 ||
    double(reader->GetLatLongWidth()) * reader->GetLatLongHeight() > double(MaxPixels))
  {
    vsfuzz::Fail("lat-long size " + std::to_string(reader->GetLatLongWidth()) + " x " +
      std::to_string(reader->GetLatLongHeight()) + " is empty or above MaximumNumberOfPixels");
  }
  return 0;
}
