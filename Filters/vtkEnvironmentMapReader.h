/**
 * @class   vtkEnvironmentMapReader
 * @brief   Reads an equirectangular HDR environment into an octahedral map.
 *
 * Reads a lat-long (equirectangular) environment of linear radiance, in the
 * orientation of docs/reference.md (column u in [0,1) is the azimuth phi = 2 pi (0.5 - u)
 * from +X towards +Y, row v the polar angle theta = pi v from +Z: +Z is up and
 * the image centre looks along +X), and converts it to the equal-area octahedral
 * map the renderer samples, by integrating the source over each texel (not by
 * point sampling), with its luminance importance quadtree. The output layout is
 * described in vtkEnvironmentMapAlgorithm.
 *
 * Formats, recognised by their content (not the extension):
 *  - OpenEXR (the OpenEXR library): half or float, scanline or tiled, RGB or
 *    RGBA (alpha ignored), a luminance-only Y channel, or luminance/chroma
 *    (Y, RY, BY); a layer prefix ("rgba.R") is accepted when there is no plain R/G/B.
 *  - Radiance RGBE .hdr / .pic (VTK's vtkHDRReader).
 *
 * A missing, unreadable or corrupt file, or one larger than MaximumNumberOfPixels, is
 * an error (vtkErrorMacro naming the file and the reason) and leaves the output empty. Source pixels with a NaN,
 * infinite or negative channel have those channels replaced by 0, with one
 * warning giving the count; negatives of at most 1% of the map's mean luminance (the
 * ringing of lossy compression that real HDRIs, the shipped ones too, carry) are zeroed
 * without a warning (vs::EnvironmentMap::RingingTexels counts them).
 *
 * @code{.py}
 * import vissweep
 * r = vissweep.vtkEnvironmentMapReader()
 * r.SetFileName("forest.exr")
 * r.SetRotationDegrees(90)   # turn the environment about +Z
 * r.Update()
 * print(r.GetOutput().GetDimensions(), r.GetTotalPower())
 * @endcode
 */
#ifndef vtkEnvironmentMapReader_h
#define vtkEnvironmentMapReader_h

#include "vissweepFiltersModule.h"
#include "vtkEnvironmentMapAlgorithm.h"

#if !defined(__VTK_WRAP__)
#include <string> // for std::string
namespace vs
{
struct LatLongImage;
}
#endif

class VISSWEEPFILTERS_EXPORT vtkEnvironmentMapReader : public vtkEnvironmentMapAlgorithm
{
public:
  static vtkEnvironmentMapReader* New();
  vtkTypeMacro(vtkEnvironmentMapReader, vtkEnvironmentMapAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The lat-long file (.exr, .hdr, .pic). */
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /**
   * Edge of the octahedral map in texels: a power of two, or 0 (default) for the
   * smallest power of two >= half the source width (1024 x 512 -> 512).
   */
  vtkSetClampMacro(OctahedralSize, int, 0, 32768);
  vtkGetMacro(OctahedralSize, int);
  ///@}

  ///@{
  /**
   * Rotation of the environment about +Z, in degrees: the radiance arriving from
   * direction d is the file's at R_z(-rotation) d (what the file shows at +X
   * appears at +Y after +90). Default 0.
   */
  vtkSetMacro(RotationDegrees, double);
  vtkGetMacro(RotationDegrees, double);
  ///@}

  ///@{
  /**
   * Largest source image (pixels of the display window, and of an OpenEXR data window)
   * the reader will allocate; a file claiming more is an error, reported before any
   * allocation. A guard against corrupt headers: a few hundred bytes can claim an image of
   * 10^9 pixels. Default 2^28 (16384 x 16384; 3 GiB as RGB floats).
   */
  vtkSetClampMacro(MaximumNumberOfPixels, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfPixels, vtkIdType);
  ///@}

  /** 1 when the file exists and starts like an OpenEXR or Radiance HDR file. */
  static int CanReadFile(VTK_FILEPATH const char* fileName);

  ///@{
  /** Size of the lat-long source of the last execution (0 before). */
  vtkGetMacro(LatLongWidth, int);
  vtkGetMacro(LatLongHeight, int);
  ///@}

#if !defined(__VTK_WRAP__)
  /**
   * Reads a lat-long file into image (row 0 = top = +Z). Returns false with the
   * reason in error (naming the file) when it cannot (also for a file larger than the
   * default MaximumNumberOfPixels, 2^28). Never throws.
   */
  static bool ReadLatLong(const char* fileName, vs::LatLongImage& image, std::string& error);
#endif

protected:
  vtkEnvironmentMapReader();
  ~vtkEnvironmentMapReader() override;

#if !defined(__VTK_WRAP__)
  int ComputeOutputSize() override;
  std::shared_ptr<vs::EnvironmentMap> ComputeMap() override;
  std::string DescribeSource() override;
#endif

  char* FileName = nullptr;
  int OctahedralSize = 0;
  double RotationDegrees = 0.0;
  int LatLongWidth = 0;
  int LatLongHeight = 0;
  vtkIdType MaximumNumberOfPixels = vtkIdType(1) << 28;

private:
  vtkEnvironmentMapReader(const vtkEnvironmentMapReader&) = delete;
  void operator=(const vtkEnvironmentMapReader&) = delete;
};

#endif
