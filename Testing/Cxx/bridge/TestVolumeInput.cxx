// The scalars as floats (what the mapper uploads) are each tuple's first component as
// GetComponent gives it, for every array layout and value type VTK hands a mapper: 8- and 16-bit
// MRI codes, int64 beyond float's and double's exact range, doubles, several components, and a
// structure-of-arrays array.
#include "vsVolumeInput.h"

#include "vtkDoubleArray.h"
#include "vtkLongLongArray.h"
#include "vtkNew.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkShortArray.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace
{
void ExpectFirstComponents(vtkDataArray* array)
{
  const std::vector<float> values = vs::ScalarsAsFloat(array);
  ASSERT_EQ(values.size(), size_t(array->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    const float expected = static_cast<float>(array->GetComponent(i, 0));
    ASSERT_EQ(std::memcmp(&values[size_t(i)], &expected, sizeof(float)), 0)
      << array->GetClassName() << " tuple " << i << ": " << values[size_t(i)] << " against " << expected;
  }
}
}

TEST(VolumeInput, ScalarsAsFloatAreTheFirstComponents)
{
  std::mt19937_64 rng(5);
  vtkNew<vtkUnsignedCharArray> bytes;
  vtkNew<vtkShortArray> shorts;
  vtkNew<vtkLongLongArray> longs;
  vtkNew<vtkDoubleArray> doubles; // two components: only the first is the scalar
  doubles->SetNumberOfComponents(2);
  vtkNew<vtkSOADataArrayTemplate<float>> soa;
  soa->SetNumberOfComponents(2);
  const vtkIdType n = 1000;
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(bytes), static_cast<vtkDataArray*>(shorts),
         static_cast<vtkDataArray*>(longs), static_cast<vtkDataArray*>(doubles), static_cast<vtkDataArray*>(soa) })
  {
    a->SetNumberOfTuples(n);
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    bytes->SetValue(i, static_cast<unsigned char>(rng()));
    shorts->SetValue(i, static_cast<short>(rng()));
    // Beyond 2^53: a direct int64 -> float cast may round differently from GetComponent's double.
    longs->SetValue(i, static_cast<long long>(rng() >> (i % 11)) - (1ll << 40));
    doubles->SetTypedComponent(i, 0, std::uniform_real_distribution<double>(-1e6, 1e6)(rng));
    doubles->SetTypedComponent(i, 1, 7.0);
    soa->SetTypedComponent(i, 0, std::uniform_real_distribution<float>(-5.0f, 5.0f)(rng));
    soa->SetTypedComponent(i, 1, -1.0f);
  }
  doubles->SetTypedComponent(3, 0, std::numeric_limits<double>::quiet_NaN());
  doubles->SetTypedComponent(4, 0, std::numeric_limits<double>::infinity());
  ExpectFirstComponents(bytes);
  ExpectFirstComponents(shorts);
  ExpectFirstComponents(longs);
  ExpectFirstComponents(soa);
  const std::vector<float> values = vs::ScalarsAsFloat(doubles);
  EXPECT_TRUE(std::isnan(values[3]));
  EXPECT_TRUE(std::isinf(values[4]));
  doubles->SetTypedComponent(3, 0, 0.0);
  ExpectFirstComponents(doubles);
}
