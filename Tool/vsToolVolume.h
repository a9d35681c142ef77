// vsToolVolume.h — reading volumes for the command-line tool by file type
// (.vti, .mha/.mhd, .nrrd/.nhdr, .nii/.nii.gz, a DICOM folder, .vdb), and the fixed
// transfer functions the benchmarks use.
#ifndef vsToolVolume_h
#define vsToolVolume_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

class vtkImageData;
class vtkVolumeProperty;

namespace vstool
{
/** Reads a volume; throws std::runtime_error naming the file and the reason. For .vdb, `grid`
 *  is the float grid to read. Every reader's result is checked: its error events and
 *  GetErrorCode(), MetaIO's messages, as many values as points, finite non-zero spacing and a
 *  finite origin; a path that is not a regular file (a FIFO, a device) is refused before any
 *  reader opens it, and a header claiming more than `maxPoints` points before any allocation. */
vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string& grid = "density",
  vtkIdType maxPoints = vtkIdType(1) << 31);

/** What a volume's dimensions must pass before its data is read: "" when it may be read, else the
 *  reason naming the limit (the render command checks the device's limits and the host's memory:
 *  a header of 1200^3 floats made VTK's reader allocate 6.9 GB before the device refused it). */
using VolumeSizeCheck = std::function<std::string(const std::array<int, 3>& dims)>;

/** What a volume file's header tells before its voxels are read. */
struct VolumeHeader
{
  int Extent[6];
  double Spacing[3];
  double Origin[3];
  int ScalarType; // VTK_UNSIGNED_CHAR, ...
};
/** Called with the header once it has passed the checks, before the voxels are read (the render
 *  command starts compiling its kernel then: vtkVisibilitySweepVolumeMapper::PrecompileRenderKernel). */
using VolumeHeaderSeen = std::function<void(const VolumeHeader& header)>;

/** ReadVolume with `check` run on the header's dimensions before any data is read (NIfTI,
 *  MetaImage, NRRD, .vdb); other formats are checked after reading. `seen`, when given, is told the
 *  header of NIfTI, MetaImage and NRRD files before their voxels are read. */
vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string& grid, vtkIdType maxPoints,
  const VolumeSizeCheck& check, const VolumeHeaderSeen& seen = VolumeHeaderSeen());

/** Reads time step `step` of a .vdb sequence (one file per step, a fixed extent for all steps). */
vtkSmartPointer<vtkImageData> ReadVolumeSequence(
  const std::vector<std::string>& files, const std::string& grid = "density", int step = 0);

/** The skin transfer function of the benchmarks for the Colin27 MRI (scalars 0..255). */
vtkSmartPointer<vtkVolumeProperty> SkinProperty();

/** Where Debian's mricron-data puts Colin27. */
std::string DefaultBrainPath();
}

#endif
