// The scalars uploaded where VTK holds them (issue 39, item 0): the device volume read from an
// array's own values (vsHostScalars.h, NativeScalars) is the same bits as from the float copy the
// mapper made before (ScalarsAsFloat): its r32f image, its 8-bit quads and their offset, its range,
// its non-finite count and the bricks' ranges, for 8-, 16-, 32- and 64-bit integers (negative ones,
// a span past 255, int64 beyond 2^53), floats and doubles with NaN, Inf and doubles past float's
// range. A structure-of-arrays array has no contiguous values and is converted as before; the
// scene's update then has a "convert" phase, and none for the contiguous ones.
#include "vsBrickRanges.h"
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsVolumeInput.h"
#include "vsVolumeScene.h"

#include "vtkCharArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLongArray.h"
#include "vtkLongLongArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkUnsignedLongLongArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtkVolumeProperty.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace
{
struct Uploaded
{
  std::vector<uint32_t> Image, Quads;
  float QuadOffset = 0.0f;
  std::array<float, 2> Range{ { 0.0f, 0.0f } };
  uint64_t NonFinite = 0;
  std::vector<float> BrickRanges;
};

Uploaded Read(const vs::DeviceVolume& volume, const vs::MajorantGrid& grid)
{
  Uploaded u;
  const auto d = volume.Dims();
  const size_t n = size_t(d[0]) * d[1] * d[2];
  u.Image.resize(n);
  volume.Image().Download(u.Image.data(), n * 4);
  if (volume.Quads())
  {
    u.Quads.resize(n);
    volume.Quads()->Download(u.Quads.data(), n * 4);
  }
  u.QuadOffset = volume.QuadOffset();
  u.Range = volume.Range();
  u.NonFinite = volume.NonFiniteCount();
  u.BrickRanges = grid.Ranges();
  return u;
}

// As the mapper did before: the float copy, its upload, the ranges from the copy.
Uploaded FromFloats(vtkDataArray* array, std::array<uint32_t, 3> dims)
{
  auto ctx = vs::Context::Default();
  const std::vector<float> values = vs::ScalarsAsFloat(array);
  vs::DeviceVolume volume(ctx, values.data(), dims);
  vs::MajorantGrid grid(ctx);
  grid.UpdateRanges(volume, values.data());
  return Read(volume, grid);
}

// As the scene does now: the array's own values, the ranges made slice by slice during the upload.
Uploaded FromNative(vtkDataArray* array, std::array<uint32_t, 3> dims)
{
  auto ctx = vs::Context::Default();
  const vs::HostScalars host = vs::NativeScalars(array);
  EXPECT_NE(host.Data, nullptr) << array->GetClassName();
  vs::MajorantGrid grid(ctx);
  vs::BrickRanges ranges(dims, grid.BrickSize());
  vs::DeviceVolume volume(
    ctx, host, dims, [&ranges](uint32_t z, const float* slice) { ranges.AddSlice(z, slice); });
  grid.UpdateRanges(volume, ranges);
  return Read(volume, grid);
}

void ExpectSame(const Uploaded& a, const Uploaded& b, const std::string& what)
{
  EXPECT_EQ(a.Image, b.Image) << what << ": the r32f image";
  EXPECT_EQ(a.Quads, b.Quads) << what << ": the quads";
  EXPECT_EQ(a.QuadOffset, b.QuadOffset) << what;
  EXPECT_EQ(a.Range, b.Range) << what;
  EXPECT_EQ(a.NonFinite, b.NonFinite) << what;
  ASSERT_EQ(a.BrickRanges.size(), b.BrickRanges.size()) << what;
  EXPECT_EQ(0, std::memcmp(a.BrickRanges.data(), b.BrickRanges.data(), a.BrickRanges.size() * 4))
    << what << ": the brick ranges";
}

template <typename ArrayT, typename Make>
void Check(std::array<uint32_t, 3> dims, Make make, bool quads)
{
  vtkNew<ArrayT> array;
  const vtkIdType n = vtkIdType(dims[0]) * dims[1] * dims[2];
  array->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    array->SetValue(i, make(i));
  }
  const Uploaded floats = FromFloats(array, dims), native = FromNative(array, dims);
  ExpectSame(floats, native, array->GetClassName());
  EXPECT_EQ(!native.Quads.empty(), quads) << array->GetClassName() << ": quads expected " << quads;
}
}

TEST(NativeScalars, UploadTheSameBitsAsTheFloatCopy)
{
  // Sizes that are no multiple of the brick, several slices per slab and chunk.
  const std::array<uint32_t, 3> dims{ { 19, 13, 23 } };
  std::mt19937_64 rng(17);
  Check<vtkUnsignedCharArray>(dims, [&](vtkIdType) { return static_cast<unsigned char>(rng()); }, true);
  Check<vtkSignedCharArray>(dims, [&](vtkIdType) { return static_cast<signed char>(rng()); }, true);
  Check<vtkCharArray>(dims, [&](vtkIdType) { return static_cast<char>(rng() % 100); }, true);
  // 16-bit MRI codes with an offset: negative, a span of 200 (quads with offset -1000), then past 255.
  Check<vtkShortArray>(dims, [&](vtkIdType) { return static_cast<short>(-1000 + int(rng() % 201)); }, true);
  Check<vtkShortArray>(dims, [&](vtkIdType) { return static_cast<short>(rng()); }, false);
  Check<vtkUnsignedShortArray>(dims, [&](vtkIdType) { return static_cast<unsigned short>(rng()); }, false);
  Check<vtkIntArray>(dims, [&](vtkIdType) { return static_cast<int>(rng()); }, false);
  Check<vtkUnsignedIntArray>(dims, [&](vtkIdType) { return static_cast<unsigned int>(rng() % 256 + 70000); }, true);
  Check<vtkLongArray>(dims, [&](vtkIdType i) { return static_cast<long>(i % 256) - 128; }, true);
  // Beyond 2^53: through double, as GetComponent rounds them.
  Check<vtkLongLongArray>(
    dims,
    [&](vtkIdType i) {
      // 2^60 + 2^36 + 1 rounds up to float directly, but to the tie 2^60 + 2^36 as a double first,
      // and from there to even (2^60).
      if (i % 7 == 1)
        return (1ll << 60) + (1ll << 36) + 1;
      return static_cast<long long>(rng() >> (i % 11)) - (1ll << 40);
    },
    false);
  Check<vtkUnsignedLongLongArray>(
    dims, [&](vtkIdType i) { return static_cast<unsigned long long>(rng() >> (i % 13)); }, false);
  // Integer-valued floats get quads; NaN and +-Inf are empty space (no quads); a double past float's
  // range is infinite as a float.
  Check<vtkFloatArray>(dims, [&](vtkIdType i) { return float(int(i % 37)) - 3.0f; }, true);
  Check<vtkFloatArray>(dims,
    [&](vtkIdType i) {
      if (i % 89 == 3)
        return std::numeric_limits<float>::quiet_NaN();
      if (i % 157 == 9)
        return -std::numeric_limits<float>::infinity();
      return float(rng() % 100000) * 1e-3f - 7.0f;
    },
    false);
  Check<vtkDoubleArray>(dims,
    [&](vtkIdType i) {
      if (i % 71 == 2)
        return std::numeric_limits<double>::quiet_NaN();
      if (i % 113 == 5)
        return std::numeric_limits<double>::infinity();
      if (i % 211 == 1)
        return 1e300;
      return std::uniform_real_distribution<double>(-1e6, 1e6)(rng);
    },
    false);
  // Every voxel NaN: no range, every brick empty.
  Check<vtkFloatArray>(dims, [&](vtkIdType) { return std::numeric_limits<float>::quiet_NaN(); }, false);
}

TEST(NativeScalars, OnlyContiguousSingleComponentArrays)
{
  vtkNew<vtkSOADataArrayTemplate<float>> soa;
  soa->SetNumberOfComponents(1);
  soa->SetNumberOfTuples(10);
  EXPECT_EQ(vs::NativeScalars(soa).Data, nullptr) << "structure-of-arrays: converted";
  vtkNew<vtkFloatArray> two;
  two->SetNumberOfComponents(2);
  two->SetNumberOfTuples(10);
  EXPECT_EQ(vs::NativeScalars(two).Data, nullptr) << "two components: converted";
  vtkNew<vtkUnsignedCharArray> bytes;
  bytes->SetNumberOfTuples(10);
  EXPECT_EQ(vs::NativeScalars(bytes).Data, bytes->GetVoidPointer(0));
  EXPECT_EQ(vs::NativeScalars(bytes).Kind, vs::HostScalars::Type::UInt8);
}

TEST(NativeScalars, TheSceneConvertsOnlyWhatItCannotReadInPlace)
{
  const int n = 12;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n + 1, n + 2);
  vtkNew<vtkShortArray> shorts;
  vtkNew<vtkSOADataArrayTemplate<short>> soa;
  shorts->SetNumberOfTuples(image->GetNumberOfPoints());
  soa->SetNumberOfComponents(1); // allocates its component buffers
  soa->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    const short v = static_cast<short>(-500 + (i * 7919) % 300);
    shorts->SetValue(i, v);
    soa->SetTypedComponent(i, 0, v);
  }
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(-500.0, 0.0);
  opacity->AddPoint(-200.0, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetScalarOpacity(opacity);
  std::vector<uint32_t> bits[2];
  std::vector<float> ranges[2];
  int k = 0;
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(shorts), static_cast<vtkDataArray*>(soa) })
  {
    image->GetPointData()->SetScalars(a);
    vs::VolumeScene scene(vs::Context::Default());
    scene.Update(image, a, property, nullptr, 1.0);
    const bool converted = scene.LastPhases().Seconds("convert") > 0.0 ||
      std::any_of(scene.LastPhases().Phases().begin(), scene.LastPhases().Phases().end(),
        [](const auto& p) { return p.first == "convert"; });
    EXPECT_EQ(converted, a == soa.GetPointer()) << a->GetClassName();
    bits[k].resize(size_t(image->GetNumberOfPoints()));
    scene.Volume().Image().Download(bits[k].data(), bits[k].size() * 4);
    ranges[k] = scene.Majorants().Ranges();
    ++k;
  }
  EXPECT_EQ(bits[0], bits[1]);
  EXPECT_EQ(ranges[0], ranges[1]);
}
