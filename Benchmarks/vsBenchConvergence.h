// vsBenchConvergence.h — `vissweep bench convergence SCENE.json`: error against run time
// (and against samples per pixel) for each sampling strategy, against a reference image
// (von Radziewsky et al. 2017, Figs. 9 and 10 on this machine).
#ifndef vsBenchConvergence_h
#define vsBenchConvergence_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchConvergence(CLI::App& bench);
}

#endif
