#include "vsVolumeInput.h"
#include "sampling/vs_prelude.h"
#include "vsError.h"
#include "vsFloatRange.h"
#include "vsParallelSlabs.h"

#include "vtkArrayDispatch.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObject.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace vs
{
std::string CheckImage(vtkImageData* image, vtkDataArray* scalars)
{
  if (!image)
  {
    return "no input volume (vtkImageData) is set";
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0 || image->GetNumberOfPoints() == 0)
  {
    std::ostringstream os;
    os << "the input volume has an empty extent (" << dims[0] << " x " << dims[1] << " x " << dims[2] << ")";
    return os.str();
  }
  if (!scalars)
  {
    return "the input volume has no point scalars to render";
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    std::ostringstream os;
    os << "the input scalars '" << (scalars->GetName() ? scalars->GetName() : "")
       << "' have " << scalars->GetNumberOfComponents()
       << " components; only single-component scalars are supported (neither independent components with their "
          "own transfer functions nor dependent RGBA / luminance-alpha data are rendered yet: extract one "
          "component, e.g. with vtkImageExtractComponents)";
    return os.str();
  }
  switch (scalars->GetDataType())
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
    case VTK_UNSIGNED_CHAR:
    case VTK_SHORT:
    case VTK_UNSIGNED_SHORT:
    case VTK_INT:
    case VTK_UNSIGNED_INT:
    case VTK_LONG:
    case VTK_UNSIGNED_LONG:
    case VTK_LONG_LONG:
    case VTK_UNSIGNED_LONG_LONG:
    case VTK_FLOAT:
    case VTK_DOUBLE:
      break;
    default:
      return std::string("the input scalars have the unsupported type ") + scalars->GetDataTypeAsString();
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    return "the input scalars do not match the volume's points (cell data is not supported)";
  }
  return std::string();
}

std::string CheckGeometry(const VolumeGeometry& geometry)
{
  static const char* const axis[3] = { "x", "y", "z" };
  std::ostringstream os;
  // The device works in float: index <-> world numbers must be finite there too.
  const double floatLimit = double(std::numeric_limits<float>::max());
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      const double v = geometry.IndexToWorld[c][r];
      if (!std::isfinite(v) || std::abs(v) > floatLimit)
      {
        os << "the volume's placement is not finite (index-to-world matrix entry (" << r << ", " << c
           << ") is " << v << "): check the image's spacing, origin and direction matrix and the "
           << "prop's matrix";
        return os.str();
      }
    }
  }
  // Lengths below this (or a singular matrix) have no float inverse.
  const double minLength = 1e-30, maxLength = 1e30;
  for (int i = 0; i < 3; ++i)
  {
    const double length = geometry.Spacing(i);
    if (!(length >= minLength) || !(length <= maxLength))
    {
      os << "the volume's spacing along " << axis[i] << " is " << length << " world units (with the direction "
         << "matrix and the prop's matrix); it must lie between " << minLength << " and " << maxLength;
      return os.str();
    }
  }
  const glm::dmat3 m(geometry.IndexToWorld);
  const double scale = geometry.Spacing(0) * geometry.Spacing(1) * geometry.Spacing(2);
  if (!(std::abs(glm::determinant(m)) > 1e-9 * scale))
  {
    return "the volume's index-to-world matrix is singular (its axes are parallel): check the image's "
           "direction matrix and the prop's matrix";
  }
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      const double v = geometry.WorldToIndex[c][r];
      if (!std::isfinite(v) || std::abs(v) > floatLimit)
      {
        return "the volume's world-to-index matrix does not fit in float: check the image's spacing, "
               "origin and direction matrix and the prop's matrix";
      }
    }
  }
  return std::string();
}

vtkMTimeType NewestModification(std::initializer_list<vtkObject*> objects)
{
  vtkMTimeType t = 0;
  for (vtkObject* o : objects)
  {
    if (o)
    {
      t = std::max(t, o->GetMTime());
    }
  }
  return t;
}

std::string CheckProperty(vtkVolumeProperty* property)
{
  if (!property)
  {
    return "the volume has no vtkVolumeProperty";
  }
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  if (!opacity || opacity->GetSize() == 0)
  {
    return "the scalar opacity transfer function has no points";
  }
  if (property->GetColorChannels(0) == 3)
  {
    vtkColorTransferFunction* color = property->GetRGBTransferFunction(0);
    if (!color || color->GetSize() == 0)
    {
      return "the colour transfer function has no points";
    }
  }
  if (!(property->GetScalarOpacityUnitDistance(0) > 0.0))
  {
    return "the scalar opacity unit distance must be positive";
  }
  // Transfer-function points and the unit distance must fit the device's float (issue 13, item 5).
  return FloatRange::CheckProperty(property);
}

VolumeGeometry ComputeGeometry(vtkImageData* image, vtkMatrix4x4* volumeMatrix)
{
  VolumeGeometry g;
  int dims[3];
  image->GetDimensions(dims);
  int extent[6];
  image->GetExtent(extent);
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  vtkMatrix3x3* dir = image->GetDirectionMatrix();
  // structured index -> physical: p = origin + D * diag(spacing) * ijk; array index a = ijk - extent min.
  glm::dmat4 indexToPhysical(1.0);
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      indexToPhysical[c][r] = dir->GetElement(r, c) * spacing[c];
    }
    double t = origin[r];
    for (int c = 0; c < 3; ++c)
    {
      t += dir->GetElement(r, c) * spacing[c] * extent[2 * c];
    }
    indexToPhysical[3][r] = t;
  }
  glm::dmat4 model(1.0);
  if (volumeMatrix)
  {
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        model[c][r] = volumeMatrix->GetElement(r, c);
      }
    }
  }
  g.IndexToWorld = model * indexToPhysical;
  g.WorldToIndex = glm::inverse(g.IndexToWorld);
  for (int i = 0; i < 3; ++i)
  {
    g.Dims[i] = static_cast<uint32_t>(dims[i]);
    g.BoxMin[i] = dims[i] > 1 ? 0.0f : -0.5f;
    g.BoxMax[i] = dims[i] > 1 ? float(dims[i] - 1) : 0.5f;
  }
  g.MinSpacing = 1e300;
  for (int c = 0; c < 3; ++c)
  {
    g.MinSpacing = std::min(g.MinSpacing, glm::length(glm::dvec3(g.IndexToWorld[c])));
  }
  return g;
}

VolumeGeometry CropGeometry(const VolumeGeometry& geometry, vtkImageData* image, const double planes[6])
{
  const glm::dmat4 physicalToIndex = ComputeGeometry(image, nullptr).WorldToIndex;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (int c = 0; c < 8; ++c)
  {
    glm::dvec4 p(planes[(c & 1) ? 1 : 0], planes[(c & 2) ? 3 : 2], planes[(c & 4) ? 5 : 4], 1.0);
    glm::dvec3 i(physicalToIndex * p);
    lo = glm::min(lo, i);
    hi = glm::max(hi, i);
  }
  VolumeGeometry g = geometry;
  for (int i = 0; i < 3; ++i)
  {
    g.BoxMin[i] = float(std::max(double(g.BoxMin[i]), lo[i]));
    g.BoxMax[i] = float(std::min(double(g.BoxMax[i]), hi[i]));
  }
  return g;
}

VolumeGeometry CropRegions(const VolumeGeometry& geometry, vtkImageData* image, const double planes[6], int flags)
{
  // The planes in index space: CropGeometry with the full box gives them (clamped to the box).
  const VolumeGeometry inner = CropGeometry(geometry, image, planes);
  const uint32_t visible = uint32_t(flags) & 0x7ffffffu;
  glm::vec3 lo(1e30f), hi(-1e30f);
  int regions = 0;
  for (uint32_t r = 0; r < 27; ++r)
  {
    if (!(visible & (1u << r)))
    {
      continue;
    }
    ++regions;
    const uint32_t c[3] = { r % 3, (r / 3) % 3, r / 9 };
    for (int i = 0; i < 3; ++i)
    {
      const float a = c[i] == 0 ? geometry.BoxMin[i] : c[i] == 1 ? inner.BoxMin[i] : inner.BoxMax[i];
      const float b = c[i] == 0 ? inner.BoxMin[i] : c[i] == 1 ? inner.BoxMax[i] : geometry.BoxMax[i];
      lo[i] = std::min(lo[i], a);
      hi[i] = std::max(hi[i], b);
    }
  }
  VolumeGeometry g = geometry;
  if (regions == 0)
  {
    g.BoxMin = glm::vec3(1.0f);
    g.BoxMax = glm::vec3(0.0f); // nothing visible
    return g;
  }
  g.BoxMin = glm::max(geometry.BoxMin, lo);
  g.BoxMax = glm::min(geometry.BoxMax, hi);
  if (regions > 1)
  {
    // A union of boxes: the passes test each point's region (a single region is exactly the box).
    g.CropLo = inner.BoxMin;
    g.CropHi = inner.BoxMax;
    g.CropFlags = visible;
  }
  return g;
}

std::vector<glm::dvec4> EffectiveClipPlanes(const std::vector<glm::dvec4>& planes, const VolumeGeometry& geometry)
{
  if (glm::any(glm::greaterThan(geometry.BoxMin, geometry.BoxMax)))
  {
    return {}; // cropped away: nothing to clip
  }
  glm::dvec3 corners[8];
  for (int c = 0; c < 8; ++c)
  {
    const glm::dvec4 i((c & 1) ? geometry.BoxMax.x : geometry.BoxMin.x, (c & 2) ? geometry.BoxMax.y : geometry.BoxMin.y,
      (c & 4) ? geometry.BoxMax.z : geometry.BoxMin.z, 1.0);
    corners[c] = glm::dvec3(geometry.IndexToWorld * i);
  }
  std::vector<glm::dvec4> kept;
  for (const glm::dvec4& p : planes)
  {
    const glm::dvec3 n(p);
    // Distances in units of |n| (VTK's normals need not be unit), with a tolerance of 1e-9 of the
    // box's size for a plane on a face of the box (a box widget at the volume's bounds).
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(p.w))
    {
      throw InputError("a clipping plane has a zero or non-finite normal or origin");
    }
    const double tolerance = 1e-9 * glm::length(corners[7] - corners[0]);
    double lo = 1e300, hi = -1e300;
    for (const glm::dvec3& x : corners)
    {
      const double s = (glm::dot(n, x) + p.w) / length;
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
    if (lo >= -tolerance)
    {
      continue; // keeps the whole box
    }
    if (hi < 0.0)
    {
      return { p }; // removes the whole box
    }
    kept.push_back(p);
  }
  if (kept.size() > shared::VS_MAX_CLIP_PLANES)
  {
    throw InputError(std::to_string(kept.size()) + " clipping planes cut the volume; at most " +
      std::to_string(shared::VS_MAX_CLIP_PLANES) +
      " are supported (vtkGPUVolumeRayCastMapper's limit too); planes that clip nothing of it are not counted");
  }
  return kept;
}

namespace
{
// The first component of every tuple as float, through the array's own value type (VTK's array
// dispatch): a virtual GetComponent per voxel took 30 ms of ch2's first frame. Via double, as
// GetComponent: an int64 above 2^53 rounds the same way.
// Tuples [begin, end) into out[begin, end).
struct FirstComponentAsFloat
{
  template <typename Array>
  void operator()(Array* array, float* out, vtkIdType begin, vtkIdType end) const
  {
    const auto tuples = vtk::DataArrayTupleRange(array, begin, end);
    float* o = out + begin;
    for (const auto tuple : tuples)
    {
      *o++ = static_cast<float>(static_cast<double>(tuple[0]));
    }
  }
};
}

std::vector<float> ScalarsAsFloat(vtkDataArray* scalars)
{
  const vtkIdType n = scalars->GetNumberOfTuples();
  std::vector<float> out(static_cast<size_t>(n));
  // In slabs on the host's threads (a first frame waits for it: 35 M voxels of ch2better, issue 39).
  vs::ForSlabs(uint64_t(n), [&](unsigned, uint64_t begin, uint64_t end) {
    if (!vtkArrayDispatch::Dispatch::Execute(
          scalars, FirstComponentAsFloat{}, out.data(), vtkIdType(begin), vtkIdType(end)))
    {
      for (vtkIdType i = vtkIdType(begin); i < vtkIdType(end); ++i) // an array type the dispatch does not know
      {
        out[static_cast<size_t>(i)] = static_cast<float>(scalars->GetComponent(i, 0));
      }
    }
  });
  return out;
}

HostScalars NativeScalars(vtkDataArray* scalars)
{
  if (!scalars || scalars->GetNumberOfComponents() != 1 || scalars->GetNumberOfTuples() <= 0 ||
    !scalars->HasStandardMemoryLayout())
  {
    return HostScalars();
  }
  using Type = HostScalars::Type;
  Type type;
  switch (scalars->GetDataType())
  {
    case VTK_FLOAT:
      type = Type::Float32;
      break;
    case VTK_DOUBLE:
      type = Type::Float64;
      break;
    case VTK_CHAR:
      type = std::is_signed<char>::value ? Type::Int8 : Type::UInt8;
      break;
    case VTK_SIGNED_CHAR:
      type = Type::Int8;
      break;
    case VTK_UNSIGNED_CHAR:
      type = Type::UInt8;
      break;
    case VTK_SHORT:
      type = Type::Int16;
      break;
    case VTK_UNSIGNED_SHORT:
      type = Type::UInt16;
      break;
    case VTK_INT:
      type = Type::Int32;
      break;
    case VTK_UNSIGNED_INT:
      type = Type::UInt32;
      break;
    case VTK_LONG:
      type = sizeof(long) == 8 ? Type::Int64 : Type::Int32;
      break;
    case VTK_UNSIGNED_LONG:
      type = sizeof(unsigned long) == 8 ? Type::UInt64 : Type::UInt32;
      break;
    case VTK_LONG_LONG:
      type = Type::Int64;
      break;
    case VTK_UNSIGNED_LONG_LONG:
      type = Type::UInt64;
      break;
    default:
      return HostScalars();
  }
  return HostScalars(scalars->GetVoidPointer(0), type);
}

TransferFunctionSamples SampleTransferFunction(vtkVolumeProperty* property, float smin, float smax,
  double densityScale, size_t entries)
{
  vtkPiecewiseFunction* opacity = property->GetScalarOpacity(0);
  double r[2];
  opacity->GetRange(r);
  double lo = std::min<double>(smin, r[0]), hi = std::max<double>(smax, r[1]);
  const bool rgb = property->GetColorChannels(0) == 3;
  vtkColorTransferFunction* ctf = rgb ? property->GetRGBTransferFunction(0) : nullptr;
  vtkPiecewiseFunction* gray = rgb ? nullptr : property->GetGrayTransferFunction(0);
  return TransferFunctionSamples::FromFunctions(static_cast<float>(lo), static_cast<float>(hi), entries,
    [&](double s) { return opacity->GetValue(s); },
    [&](double s, double c[3]) {
      if (ctf)
      {
        ctf->GetColor(s, c);
      }
      else if (gray && gray->GetSize() > 0)
      {
        c[0] = c[1] = c[2] = gray->GetValue(s);
      }
      else
      {
        c[0] = c[1] = c[2] = 1.0;
      }
    },
    property->GetScalarOpacityUnitDistance(0), densityScale);
}
}
