/**
 * @class   vtkEnvironmentMapAlgorithm
 * @brief   Base of the environment map sources: the octahedral map as vtkImageData.
 *
 * The common output of vtkEnvironmentMapReader and vtkEnvironmentMapSource: an
 * equal-area octahedral environment map (docs/reference.md, "Environment light and its orientation")
 * of Size x Size texels, as a vtkImageData of Size x Size x 1 points, one point
 * per texel, with
 *  - point data "Radiance" (3 floats, the active scalars): the mean linear RGB
 *    radiance over the texel's solid angle (4 pi / Size^2 steradians);
 *  - point data "Importance" (1 float): the texel's luminance
 *    (0.2126 R + 0.7152 G + 0.0722 B);
 *  - field data "ImportanceMips" (vtkFloatArray): the luminance quadtree, levels
 *    0..K (Size = 2^K) concatenated, level l = 2^l x 2^l nodes row-major starting
 *    at (4^l - 1) / 3, each node the mean of its 4 children (level 0 = the mean);
 *  - field data "BadTexels" and "NonFiniteTexels" (vtkIdTypeArray, 1 value):
 *    the source pixels with a NaN, infinite or negative channel (zeroed, one
 *    warning per execution), and those of them with a NaN or infinite one;
 *  - field data "MeanRadiance" (vtkDoubleArray, 3 values) and "TotalPower"
 *    (vtkDoubleArray, 1 value: the integral of luminance over the sphere).
 * Texel (x, y) is point (x, y): origin 0.5 / Size and spacing 1 / Size, so the
 * point coordinates are the octahedral (u, v) of the texel centres.
 *
 * From C++, GetEnvironmentMap() returns the map without converting it back, and
 * EnvironmentMapFromImage() rebuilds one from any image with this layout.
 */
#ifndef vtkEnvironmentMapAlgorithm_h
#define vtkEnvironmentMapAlgorithm_h

#include "vissweepFiltersModule.h"
#include "vtkImageAlgorithm.h"

#if !defined(__VTK_WRAP__)
#include <memory> // for std::shared_ptr
#include <string> // for std::string
namespace vs
{
class EnvironmentMap;
}
#endif

class vtkImageData;

class VISSWEEPFILTERS_EXPORT vtkEnvironmentMapAlgorithm : public vtkImageAlgorithm
{
public:
  vtkTypeMacro(vtkEnvironmentMapAlgorithm, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Scale applied to the radiance (>= 0). Default 1. */
  vtkSetClampMacro(Intensity, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Intensity, double);
  ///@}

  /** The integral of luminance over the sphere of the last output (0 when empty). */
  double GetTotalPower();
  /** Source pixels with a NaN, infinite or negative channel in the last output. */
  vtkIdType GetBadTexels();

#if !defined(__VTK_WRAP__)
  /**
   * The map of the last successful execution (null when the output is empty).
   * Shared, immutable: holding it is cheap and it stays valid after re-execution.
   */
  std::shared_ptr<const vs::EnvironmentMap> GetEnvironmentMap() const;

  /**
   * Rebuilds a map from an image with the layout above (Size x Size x 1 points,
   * Size a power of two, a 3-component "Radiance" point array of any real type;
   * the quadtree is recomputed). Null, with the reason in *error, when the image
   * does not fit.
   */
  static std::shared_ptr<const vs::EnvironmentMap> EnvironmentMapFromImage(
    vtkImageData* image, std::string* error = nullptr);

  /**
   * Whether image has the layout above (what EnvironmentMapFromImage() accepts), without
   * building a map: false, with the reason in *error, when it does not fit.
   */
  static bool IsEnvironmentMapImage(vtkImageData* image, std::string* error = nullptr);

  /** Fills image with the layout above from map (empties it when map is empty). */
  static void FillImage(const vs::EnvironmentMap& map, vtkImageData* image);
#endif

protected:
  vtkEnvironmentMapAlgorithm();
  ~vtkEnvironmentMapAlgorithm() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

#if !defined(__VTK_WRAP__)
  /**
   * The octahedral size the next execution will produce, or 0 after reporting
   * an error (vtkErrorMacro) when it cannot be known (e.g. a missing file).
   */
  virtual int ComputeOutputSize() = 0;
  /**
   * Computes the map, reporting progress in [0, 1] through UpdateProgress; null
   * after reporting an error with vtkErrorMacro.
   */
  virtual std::shared_ptr<vs::EnvironmentMap> ComputeMap() = 0;
  /** Names the map in messages (the file name, or the procedural type). */
  virtual std::string DescribeSource() = 0;
#endif

  double Intensity = 1.0;

private:
  vtkEnvironmentMapAlgorithm(const vtkEnvironmentMapAlgorithm&) = delete;
  void operator=(const vtkEnvironmentMapAlgorithm&) = delete;

#if !defined(__VTK_WRAP__)
  std::shared_ptr<const vs::EnvironmentMap> Map;
#endif
  bool InformationFailed = false;
};

#endif
