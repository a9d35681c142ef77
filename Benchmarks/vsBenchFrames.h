// vsBenchFrames.h — `vissweep bench frames [SCENE]`: wall-clock frame times of the mapper
// in a window, while the user drags (interactive: subsampled, one sample per pixel) and
// once the view is still (full resolution, progressive).
#ifndef vsBenchFrames_h
#define vsBenchFrames_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchFrames(CLI::App& bench);
}

#endif
