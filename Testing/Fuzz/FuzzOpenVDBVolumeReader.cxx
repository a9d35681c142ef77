// libFuzzer target: vtkOpenVDBVolumeReader. The input bytes are written to a scratch .vdb
// file and read (grid listing, then the "density" grid). Contract under test
// (vtkOpenVDBVolumeReader.h): a missing grid, a corrupt or truncated file, an unsupported
// transform or a too large output is an error that leaves the output empty; otherwise the
// output is a non-empty image of float point scalars with positive, finite spacing and at
// most MaximumNumberOfPoints points. Never a crash, a sanitizer report or an unbounded
// allocation (the reader's structure check exists to stop OpenVDB 10 from trusting sizes).
//
// Harness limit: MaximumNumberOfPoints is lowered to 2^18 (a 1 MiB float volume) so that
// large but valid volumes do not slow the fuzzer down; the limit path itself is under test.
#include "vtkOpenVDBVolumeReader.h"

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
constexpr vtkIdType MaxPoints = vtkIdType(1) << 18;
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vsfuzz::SilenceVTK(); // errors are expected for most inputs; observers count them
  vtkSMPTools::Initialize(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  const std::string& path = vsfuzz::ScratchFile(".vdb");
  vsfuzz::WriteFile(path, data, size);

  vsfuzz::ErrorCount errors;

  vtkNew<vtkOpenVDBVolumeReader> reader;
  errors.Watch(reader);
  reader->SetFileName(path.c_str());
  reader->SetMaximumNumberOfPoints(MaxPoints);
  reader->UpdateInformation();
  // The grid listing is public API; every entry must be readable whatever the file said.
  const int grids = reader->GetNumberOfGrids();
  if (grids < 0)
  {
    vsfuzz::Fail("negative grid count");
  }
  for (int i = 0; i < grids; ++i)
  {
    const char* name = reader->GetGridName(i);
    const char* type = reader->GetGridType(i);
    if (!name || !type)
    {
      vsfuzz::Fail("grid " + std::to_string(i) + " of " + std::to_string(grids) + " has no name or type");
    }
    double b[6];
    int ib[6];
    reader->GetGridBounds(i, b);
    reader->GetGridIndexBounds(i, ib);
    (void)reader->GetGridActiveVoxelCount(i);
  }
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
  if (points <= 0 || points > MaxPoints)
  {
    vsfuzz::Fail("no error, but the output has " + std::to_string(points) + " points");
  }
  vtkDataArray* scalars = out->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfTuples() != points || scalars->GetNumberOfComponents() != 1 ||
    scalars->GetDataType() != VTK_FLOAT)
  {
    vsfuzz::Fail("no error, but the output has no float scalar per point");
  }
  double spacing[3], origin[3];
  out->GetSpacing(spacing);
  out->GetOrigin(origin);
  for (int k = 0; k < 3; ++k)
  {
    if (!(spacing[k] > 0.0) || !std::isfinite(spacing[k]) || !std::isfinite(origin[k]))
    {
      vsfuzz::Fail("no error, but spacing " + std::to_string(spacing[k]) + " / origin " +
        std::to_string(origin[k]) + " on axis " + std::to_string(k) + " is not positive and finite");
    }
  }
  return 0;
}
