// vsFloatRange.h — the numbers VisSweep hands to the device must fit a float. A finite double
// beyond float's range (|v| > 3.40282e+38) became an infinity there, and one below float's
// smallest normal number a zero or a denormal: an environment intensity of 1e39 gave an all-NaN
// image, a transfer-function point at 1e39 an empty table, a clip-plane normal of 1e300 an
// ignored plane (issue 13, item 5). These checks say which value and which limit, so the scene
// file, the mapper's setters and its Render() refuse such values instead of rendering a wrong
// image. A direction is different: only its way matters, so it is normalised in double first.
// Internal to VisSweep (hidden from the wrappers).
#ifndef vsFloatRange_h
#define vsFloatRange_h

#if !defined(__VTK_WRAP__)
#include "vissweepBridgeModule.h"

#include <limits>
#include <string>

class vtkCamera;
class vtkVolumeProperty;

namespace vs
{
class VISSWEEPBRIDGE_EXPORT FloatRange
{
public:
  /** The largest magnitude a float holds (3.40282e+38) and its smallest normal number (1.17549e-38). */
  static constexpr double Max = double(std::numeric_limits<float>::max());
  static constexpr double MinNormal = double(std::numeric_limits<float>::min());

  /** "" when `v` is finite and |v| <= Max, else why not (a phrase naming the limit). */
  static std::string Check(double v);
  /** "" when `v` is finite and MinNormal <= v <= Max (a positive length or scale whose float must
   *  be neither zero, denormal nor infinite), else why not. */
  static std::string CheckPositive(double v);

  /** "" when every transfer-function point of component 0 (opacity, colour or gray) lies at a
   *  scalar within float's range and the unit distance fits (CheckPositive), else the reason. */
  static std::string CheckProperty(vtkVolumeProperty* property);

  /** "" when the camera's position, focal point, view angle, parallel scale (parallel
   *  projection only) and clipping range fit a float, else the reason naming the value. */
  static std::string CheckCamera(vtkCamera* camera);

  /** `in` as a unit vector computed in double without overflow or underflow (scaled by its largest
   *  component first): (1e300, 0, 0) -> (1, 0, 0). False (and `out` untouched) when `in` is zero
   *  or not finite. */
  static bool Normalize(const double in[3], double out[3]);
};
}
#endif

#endif
