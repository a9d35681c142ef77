// vsOpenEXRLatLong.h — reading an OpenEXR lat-long for vtkEnvironmentMapReader: the header checked
// against the file before OpenEXR trusts it, any of R/G/B (or a layer's), Y or luminance/chroma,
// and the data window placed in the display window. Internal to VisSweep (hidden from the wrappers).
#ifndef vsOpenEXRLatLong_h
#define vsOpenEXRLatLong_h

#if !defined(__VTK_WRAP__)
#include <cstdint>
#include <functional>
#include <string>

namespace vs
{
struct LatLongImage;

/** Reads an OpenEXR lat-long into `image` (only its dimensions when `image` is null). Pixels
 *  outside the data window but inside the display window are black. False, with the reason in
 *  `error`, for a corrupt or unreadable file or one larger than maxPixels. `progress` (may be
 *  empty) gets the fraction of the rows read. */
bool ReadOpenEXRLatLong(const char* fileName, LatLongImage* image, int& width, int& height, std::string& error,
  const std::function<void(double)>& progress, int64_t maxPixels);
}
#endif

#endif
