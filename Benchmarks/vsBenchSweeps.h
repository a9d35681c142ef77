// vsBenchSweeps.h — `vissweep bench sweeps`: the paper's Table 1 on this machine.
#ifndef vsBenchSweeps_h
#define vsBenchSweeps_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchSweeps(CLI::App& bench);
}

#endif
