// vsBenchKernels.h — `vissweep bench kernels`: how long the render kernel's pipelines take to make,
// with the specialization constants folded into the module first (vsSpirvSpecialization.h) and
// with the whole module handed to the driver, alternated in one process.
#ifndef vsBenchKernels_h
#define vsBenchKernels_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchKernels(CLI::App& bench);
}

#endif
