// vsLatLongFileMessages.h — what the environment map file readers (vtkEnvironmentMapReader's
// Radiance HDR reading, vsOpenEXRLatLong) say about a file: its name in quotes, and the refusal
// of an image larger than MaximumNumberOfPixels. Internal to VisSweep (hidden from the wrappers).
#ifndef vsLatLongFileMessages_h
#define vsLatLongFileMessages_h

#if !defined(__VTK_WRAP__)
#include <cstdint>
#include <string>

namespace vs
{
/** "\"<fileName>\"" (an empty name for nullptr). */
std::string QuoteFileName(const char* fileName);
/** "the <what> of <file> is W x H = N pixels, more than MaximumNumberOfPixels (M)", or "" when it fits. */
std::string TooLargeMessage(const char* fileName, const char* what, int64_t w, int64_t h, int64_t maxPixels);
}
#endif

#endif
