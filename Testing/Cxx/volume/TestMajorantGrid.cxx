// The majorant grid's brick ranges: the host's separable computation (what the mapper uses, from
// the scalars it uploads) equals the device pass (majorant_minmax.comp) bit for bit, NaN and Inf
// voxels, a one-voxel-thick axis and sizes that are no multiple of the brick included; and the
// controls are lower bounds of every voxel's extinction in the brick.
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsMajorantGrid.h"
#include "vsTransferFunctionTable.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

TEST(MajorantGrid, HostRangesEqualTheDevicePass)
{
  auto context = vs::Context::Default();
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3.0f, 5.0f);
  for (std::array<uint32_t, 3> dims : { std::array<uint32_t, 3>{ 37, 20, 9 }, std::array<uint32_t, 3>{ 17, 1, 33 },
         std::array<uint32_t, 3>{ 8, 9, 16 }, std::array<uint32_t, 3>{ 1, 1, 1 } })
  {
    std::vector<float> v(size_t(dims[0]) * dims[1] * dims[2]);
    for (size_t i = 0; i < v.size(); ++i)
    {
      v[i] = u(rng);
      if (i % 97 == 5)
        v[i] = std::numeric_limits<float>::quiet_NaN();
      if (i % 131 == 7)
        v[i] = std::numeric_limits<float>::infinity();
    }
    if (dims[0] == 37)
    {
      for (uint32_t z = 0; z < dims[2]; ++z) // a brick's worth of non-finite voxels: an empty range
        for (uint32_t y = 0; y < 9; ++y)
          for (uint32_t x = 0; x < 9; ++x)
            v[(size_t(z) * dims[1] + y) * dims[0] + x] = std::numeric_limits<float>::quiet_NaN();
    }
    vs::DeviceVolume volume(context, v.data(), dims);
    vs::MajorantGrid device(context), host(context);
    device.UpdateRanges(volume);
    host.UpdateRanges(volume, v.data());
    ASSERT_EQ(device.Bricks(), host.Bricks());
    ASSERT_EQ(device.Ranges().size(), host.Ranges().size());
    for (size_t i = 0; i < device.Ranges().size(); ++i)
    {
      ASSERT_EQ(device.Ranges()[i], host.Ranges()[i]) << "dims " << dims[0] << " x " << dims[1] << " x " << dims[2]
                                                      << ", float " << i;
    }
    EXPECT_EQ(host.LastSeconds(), 0.0);

    // Controls: at most the extinction of every finite voxel of the brick's footprint, 0 with a gap.
    auto tf = vs::TransferFunctionSamples::FromFunctions(-3.0f, 5.0f, 257,
      [](double s) { return 0.2 + 0.1 * std::sin(s); }, [](double, double c[3]) { c[0] = c[1] = c[2] = 1.0; }, 1.0,
      1.0);
    host.UpdateMajorants(tf);
    const auto b = host.Bricks();
    for (uint32_t bz = 0; bz < b[2]; ++bz)
      for (uint32_t by = 0; by < b[1]; ++by)
        for (uint32_t bx = 0; bx < b[0]; ++bx)
        {
          const size_t k = (size_t(bz) * b[1] + by) * b[0] + bx;
          const float c = host.Controls()[k], m = host.Majorants()[k];
          EXPECT_LE(c, m);
          bool gap = false;
          for (uint32_t z = bz * 8; z <= std::min(bz * 8 + 8, dims[2] - 1); ++z)
            for (uint32_t y = by * 8; y <= std::min(by * 8 + 8, dims[1] - 1); ++y)
              for (uint32_t x = bx * 8; x <= std::min(bx * 8 + 8, dims[0] - 1); ++x)
              {
                const float s = v[(size_t(z) * dims[1] + y) * dims[0] + x];
                if (!std::isfinite(s))
                {
                  gap = true;
                  continue;
                }
                const float e = tf.MaxExtinction(s, s); // the voxel's own extinction
                ASSERT_LE(c, e * (1.0f + 1e-6f));
                ASSERT_GE(m, tf.MinExtinction(s, s));
              }
          if (gap)
            EXPECT_EQ(c, 0.0f);
        }
  }
}
