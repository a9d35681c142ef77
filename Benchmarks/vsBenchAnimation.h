// vsBenchAnimation.h — `vissweep bench animation SCENE.json [--frames A:B] [--budget-per-frame S]
// [--reference-spp N] [--json OUT]`: lazy visibility updates at equal time per frame (von Radziewsky et al. 2017,
// Sec. 9). For each method (Full, RoundRobin, EnvironmentGuided, Static with TwoStep sampling,
// and Environment sampling without any sweep), every time step of the scene's volume sequence
// is rendered with the same wall time per frame (update + render, the paper's adjusted
// equal-time comparison) and compared with a per-frame TwoStep reference of --reference-spp
// samples (its own seed): per-frame MSE, its mean over the sequence and over the first and
// last (up to) 20 frames, and the update cost per frame. The first step of the range is
// rendered untimed (every method computes the whole grid for it); the timed steps follow.
#ifndef vsBenchAnimation_h
#define vsBenchAnimation_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchAnimation(CLI::App& bench);
}

#endif
