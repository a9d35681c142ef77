// libFuzzer target: the command-line tool's volume loading (vstool::ReadVolume, vsToolVolume.cxx)
// over VTK's NIfTI, MetaImage and NRRD readers. The first input byte picks the format (modulo 4:
// .nii, .nii.gz, .mha, .nrrd); the rest is written to a scratch file of that extension and read.
//
// Not in the test command's short fuzzing run (only its seeds run there): within seconds to a
// minute, Debian's VTK 9.1 readers themselves crash on hostile headers (a SIGBUS in
// vtkNIFTIImageReader::RequestInformation, a heap overflow in MetaIO's MetaImage::ReadStream, an
// endless loop in vtkNrrdReader::ReadHeader; reproducers in Testing/Fuzz/open-findings/), so a
// 20 s run would fail the suite by chance. Two findings were fixed in vsToolVolume (a NRRD
// without "dimension" crashed the raw read; a MetaImage without a data file asked for 2^63
// bytes). Run it with scripts/fuzz.sh SECONDS volume_file.
// Contract under test (vsToolVolume.h): either std::runtime_error naming the file, or a non-empty
// image with one scalar per point, at most MaxPoints points, finite non-zero spacing and a finite
// origin. Never a crash, a sanitizer report, a hang or an unbounded allocation (a header's size
// is checked before the data is read).
//
// Harness limit: volumes above 2^18 points are refused (the limit path itself is under test).
#include "vsToolVolume.h"

#include "vsFuzzUtilities.h"
#include "vsFuzzVTK.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace
{
constexpr vtkIdType MaxPoints = vtkIdType(1) << 18;
constexpr int Formats = 4;
const char* const Extensions[Formats] = { ".nii", ".nii.gz", ".mha", ".nrrd" };

// One scratch file per extension (the readers pick the format by name), removed at exit.
const std::string& ScratchFor(int format)
{
  static std::string paths[Formats];
  static bool registered = false;
  if (paths[format].empty())
  {
    paths[format] = (std::filesystem::temp_directory_path() /
      ("vissweep_fuzz_volume_" + std::to_string(::getpid()) + Extensions[format])).string();
  }
  if (!registered)
  {
    registered = true;
    std::atexit([] {
      for (const auto& p : paths)
      {
        if (!p.empty())
        {
          std::remove(p.c_str());
        }
      }
    });
  }
  return paths[format];
}
}

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vsfuzz::SilenceVTK(); // errors are expected for most inputs; ReadVolume turns them into exceptions
  vtkSMPTools::Initialize(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const int format = data[0] % Formats;
  const std::string& path = ScratchFor(format);
  vsfuzz::WriteFile(path, data + 1, size - 1);
  vtkSmartPointer<vtkImageData> image;
  try
  {
    image = vstool::ReadVolume(path, "density", MaxPoints);
  }
  catch (const std::runtime_error& e)
  {
    if (std::string(e.what()).find(path) == std::string::npos)
    {
      vsfuzz::Fail(std::string("the error does not name the file: ") + e.what());
    }
    return 0;
  }
  catch (const std::exception& e)
  {
    vsfuzz::Fail(std::string("an exception that is not the documented error: ") + e.what());
  }
  const vtkIdType points = image ? image->GetNumberOfPoints() : 0;
  if (points <= 0 || points > MaxPoints)
  {
    vsfuzz::Fail("no error, but the output has " + std::to_string(points) + " points");
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfTuples() != points)
  {
    vsfuzz::Fail("no error, but the output has no scalar per point");
  }
  double spacing[3], origin[3];
  image->GetSpacing(spacing);
  image->GetOrigin(origin);
  for (int k = 0; k < 3; ++k)
  {
    if (spacing[k] == 0.0 || !std::isfinite(spacing[k]) || !std::isfinite(origin[k]))
    {
      vsfuzz::Fail("no error, but spacing " + std::to_string(spacing[k]) + " / origin " +
        std::to_string(origin[k]) + " on axis " + std::to_string(k));
    }
  }
  return 0;
}
