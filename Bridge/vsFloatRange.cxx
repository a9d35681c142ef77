#include "vsFloatRange.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vs
{
namespace
{
std::string Text(double v)
{
  std::ostringstream os;
  os << v;
  return os.str();
}

// The first node of `f` outside float's range, as "point i at scalar x: reason".
std::string CheckNodes(vtkPiecewiseFunction* f, const char* what)
{
  for (int i = 0; f && i < f->GetSize(); ++i)
  {
    double node[4];
    f->GetNodeValue(i, node);
    const std::string p = FloatRange::Check(node[0]);
    if (!p.empty())
    {
      return std::string("the ") + what + "'s point " + std::to_string(i) + " at scalar " + Text(node[0]) + ": " + p;
    }
  }
  return std::string();
}
}

std::string FloatRange::Check(double v)
{
  if (std::isnan(v))
  {
    return "not a number";
  }
  if (!(std::abs(v) <= Max))
  {
    return "outside the range of float, which the device computes in (magnitude at most " + Text(Max) + ")";
  }
  return std::string();
}

std::string FloatRange::CheckPositive(double v)
{
  if (std::isnan(v))
  {
    return "not a number";
  }
  if (!(v >= MinNormal && v <= Max))
  {
    return "outside the range of float, which the device computes in (between " + Text(MinNormal) + " and " +
      Text(Max) + ")";
  }
  return std::string();
}

std::string FloatRange::CheckProperty(vtkVolumeProperty* property)
{
  if (!property)
  {
    return std::string();
  }
  std::string p = CheckNodes(property->GetScalarOpacity(0), "scalar opacity transfer function");
  if (p.empty() && property->GetColorChannels(0) == 3)
  {
    vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
    for (int i = 0; color && i < color->GetSize() && p.empty(); ++i)
    {
      double node[6];
      color->GetNodeValue(i, node);
      const std::string q = Check(node[0]);
      if (!q.empty())
      {
        p = "the colour transfer function's point " + std::to_string(i) + " at scalar " + Text(node[0]) + ": " + q;
      }
    }
  }
  else if (p.empty())
  {
    p = CheckNodes(property->GetGrayTransferFunction(0), "gray transfer function");
  }
  if (p.empty())
  {
    const double u = property->GetScalarOpacityUnitDistance(0);
    const std::string q = CheckPositive(u);
    if (!q.empty() && u > 0.0)
    {
      p = "the scalar opacity unit distance " + Text(u) + " is " + q;
    }
  }
  return p;
}

std::string FloatRange::CheckCamera(vtkCamera* camera)
{
  if (!camera)
  {
    return std::string();
  }
  static const char* const axis[3] = { "x", "y", "z" };
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  for (int i = 0; i < 3; ++i)
  {
    std::string p = Check(position[i]);
    if (!p.empty())
    {
      return std::string("the camera's position (") + axis[i] + " = " + Text(position[i]) + ") is " + p;
    }
    p = Check(focal[i]);
    if (!p.empty())
    {
      return std::string("the camera's focal point (") + axis[i] + " = " + Text(focal[i]) + ") is " + p;
    }
  }
  if (camera->GetParallelProjection())
  {
    const std::string p = CheckPositive(camera->GetParallelScale());
    if (!p.empty())
    {
      return "the camera's parallel scale " + Text(camera->GetParallelScale()) + " is " + p;
    }
  }
  double range[2];
  camera->GetClippingRange(range);
  for (int i = 0; i < 2; ++i)
  {
    const std::string p = Check(range[i]);
    if (!p.empty())
    {
      return std::string("the camera's clipping range (") + (i ? "far" : "near") + " = " + Text(range[i]) + ") is " + p;
    }
  }
  return std::string();
}

bool FloatRange::Normalize(const double in[3], double out[3])
{
  const double m = std::max({ std::abs(in[0]), std::abs(in[1]), std::abs(in[2]) });
  if (!(m > 0.0) || !std::isfinite(m))
  {
    return false;
  }
  double v[3] = { in[0] / m, in[1] / m, in[2] / m }; // largest component 1: no square overflows
  const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = v[i] / length;
  }
  return true;
}
}
