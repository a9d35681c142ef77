// vsLatLongFileMessages.cxx — a file name in quotes and the refusal of oversized images, as the
// environment map file readers say them (vsLatLongFileMessages.h).
#include "vsLatLongFileMessages.h"

#include <iomanip>
#include <limits>
#include <sstream>

namespace vs
{
std::string QuoteFileName(const char* fileName)
{
  return std::string("\"") + (fileName ? fileName : "") + "\"";
}

std::string TooLargeMessage(const char* fileName, const char* what, int64_t w, int64_t h, int64_t maxPixels)
{
  // Without multiplying first: a corrupt header's 32-bit extents overflow a 64-bit product.
  if (w <= 0 || h <= 0 || w <= maxPixels / h)
  {
    return std::string();
  }
  const bool representable = w <= std::numeric_limits<int64_t>::max() / h;
  std::ostringstream pixels;
  if (representable)
  {
    pixels << w * h;
  }
  else
  {
    pixels << std::setprecision(4) << double(w) * double(h);
  }
  return "the " + std::string(what) + " of " + QuoteFileName(fileName) + " is " + std::to_string(w) + " x " +
    std::to_string(h) + " = " + pixels.str() + " pixels, more than MaximumNumberOfPixels (" +
    std::to_string(maxPixels) + ")";
}
}
