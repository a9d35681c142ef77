// vsToolVolume.h — reading volumes for the command-line tool by file type
// (.vti, .mha/.mhd, .nrrd/.nhdr, .nii/.nii.gz, a DICOM folder), and the fixed
// transfer functions the benchmarks use.
#ifndef vsToolVolume_h
#define vsToolVolume_h

#include "vtkSmartPointer.h"

#include <string>

class vtkImageData;
class vtkVolumeProperty;

namespace vstool
{
/** Reads a volume; throws std::runtime_error naming the file and the reason. */
vtkSmartPointer<vtkImageData> ReadVolume(const std::string& path, const std::string& grid = "density");

/** The skin transfer function of the benchmarks for the Colin27 MRI (scalars 0..255). */
vtkSmartPointer<vtkVolumeProperty> SkinProperty();

/** Where Debian's mricron-data puts Colin27. */
std::string DefaultBrainPath();
}

#endif
