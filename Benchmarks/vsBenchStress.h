// vsBenchStress.h — `vissweep bench stress [SCENE]`: the long variants of the stress suite
// (Testing/Stress runs the fast ones): many random changes with a render after each, and a
// very long accumulation, reporting errors, non-finite pixels, memory growth and drift.
#ifndef vsBenchStress_h
#define vsBenchStress_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchStress(CLI::App& bench);
}

#endif
