// vsImageOutput.h — the images `vissweep render` writes: linear EXR from the mapper's radiance,
// tone-mapped PNG from the window, and the checks of output names made before rendering.
#ifndef vsImageOutput_h
#define vsImageOutput_h

#include <string>

class vtkImageData;
class vtkRenderWindow;

namespace vstool
{
/** The lower-case extension of a path, with the dot (".exr"). */
std::string Extension(const std::string& path);
/** Throws std::runtime_error naming the option when an output is not .exr/.png or its folder is missing. */
void CheckOutputPath(const std::string& path);
/** The radiance image (arrays "Radiance", optional "Alpha") as a float RGBA EXR, rows top-down. */
void WriteExr(vtkImageData* radiance, const std::string& path);
/** The window as shown (tone mapped), without re-rendering (a re-render would add samples). */
void WritePng(vtkRenderWindow* window, const std::string& path);
}

#endif
