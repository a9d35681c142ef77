// vsBenchDenoise.h — `vissweep bench denoise SCENE.json` (issue 39, item 5): the relative MSE of what the
// window shows, against a converged Monte Carlo render of the view, at given seconds after the view became
// still: the estimate alone, the hand-over from the preview (the blend of least expected error), the
// estimate through the display filter guided by the preview (DisplayDenoise), and both.
#ifndef vsBenchDenoise_h
#define vsBenchDenoise_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchDenoise(CLI::App& bench);
}

#endif
