// The scene's host work in slabs (vsParallelSlabs.h, issue 39): every item is visited once whatever
// the thread count, an exception of any slab reaches the caller, and the device volume (its float
// image, quads, range, non-finite count) and the brick ranges are the same bits with 1, 2, 3 or 7
// threads as with one.
#include "vsContext.h"
#include "vsDeviceVolume.h"
#include "vsImage.h"
#include "vsMajorantGrid.h"
#include "vsParallelSlabs.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct HostThreads
{
  explicit HostThreads(int n) { setenv("VISSWEEP_HOST_THREADS", std::to_string(n).c_str(), 1); }
  ~HostThreads() { unsetenv("VISSWEEP_HOST_THREADS"); }
};

struct VolumeBits
{
  std::vector<uint32_t> Image, Quads;
  std::vector<float> Ranges;
  std::array<float, 2> Range;
  uint64_t NonFinite;
};

VolumeBits Upload(const std::vector<float>& v, std::array<uint32_t, 3> dims)
{
  auto ctx = vs::Context::Default();
  vs::DeviceVolume volume(ctx, v.data(), dims);
  VolumeBits bits;
  bits.Image.resize(v.size());
  volume.Image().Download(bits.Image.data(), v.size() * 4);
  if (volume.Quads())
  {
    bits.Quads.resize(v.size());
    volume.Quads()->Download(bits.Quads.data(), v.size() * 4);
  }
  vs::MajorantGrid grid(ctx);
  grid.UpdateRanges(volume, v.data());
  bits.Ranges = grid.Ranges();
  bits.Range = volume.Range();
  bits.NonFinite = volume.NonFiniteCount();
  return bits;
}
}

TEST(ParallelSlabs, VisitsEveryItemOnceAndRethrows)
{
  for (int threads : { 1, 2, 3, 8 })
  {
    HostThreads t(threads);
    for (uint64_t count : { uint64_t(0), uint64_t(1), uint64_t(2), uint64_t(5), uint64_t(1000) })
    {
      std::vector<std::atomic<int>> seen(count);
      std::atomic<unsigned> slabs{ 0 };
      vs::ForSlabs(count, [&](unsigned, uint64_t b, uint64_t e) {
        ++slabs;
        for (uint64_t i = b; i < e; ++i)
          ++seen[i];
      });
      EXPECT_EQ(slabs.load(), vs::SlabCount(count));
      EXPECT_LE(vs::SlabCount(count), unsigned(std::max<uint64_t>(1, std::min<uint64_t>(count, threads))));
      for (uint64_t i = 0; i < count; ++i)
        EXPECT_EQ(seen[i].load(), 1) << threads << " threads, item " << i << " of " << count;
    }
    EXPECT_THROW(vs::ForSlabs(100,
                   [](unsigned slab, uint64_t, uint64_t) {
                     if (slab == vs::SlabCount(100) - 1)
                       throw std::runtime_error("last slab");
                   }),
      std::runtime_error);
  }
}

TEST(ParallelSlabs, VolumeAndRangesAreTheSameBitsForAnyThreadCount)
{
  std::mt19937 rng(11);
  const std::array<uint32_t, 3> dims{ { 23, 9, 37 } };
  std::vector<float> coded(size_t(dims[0]) * dims[1] * dims[2]), real(coded.size());
  for (size_t i = 0; i < coded.size(); ++i)
  {
    coded[i] = float(int(rng() % 200)) - 50.0f; // integer-coded: quads
    real[i] = float(rng() % 100000) * 1e-3f - 7.0f;
    if (i % 89 == 3)
      real[i] = std::numeric_limits<float>::quiet_NaN();
    if (i % 157 == 9)
      real[i] = -std::numeric_limits<float>::infinity();
  }
  for (const auto* v : { &coded, &real })
  {
    VolumeBits serial;
    {
      HostThreads t(1);
      serial = Upload(*v, dims);
    }
    EXPECT_EQ(serial.Quads.empty(), v == &real);
    for (int threads : { 2, 3, 7 })
    {
      HostThreads t(threads);
      const VolumeBits parallel = Upload(*v, dims);
      EXPECT_EQ(parallel.Image, serial.Image) << threads << " threads";
      EXPECT_EQ(parallel.Quads, serial.Quads) << threads << " threads";
      EXPECT_EQ(parallel.Range, serial.Range) << threads << " threads";
      EXPECT_EQ(parallel.NonFinite, serial.NonFinite) << threads << " threads";
      ASSERT_EQ(parallel.Ranges.size(), serial.Ranges.size());
      EXPECT_EQ(0, std::memcmp(parallel.Ranges.data(), serial.Ranges.data(), serial.Ranges.size() * 4))
        << threads << " threads";
    }
  }
}
