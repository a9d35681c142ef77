// vsBenchPreview.h — `vissweep bench preview SCENE.json`: the deterministic render modes (emission-
// absorption, its Phong shading, ambient occlusion, the preview) and Monte Carlo at 1, 4, 16 and 64 spp
// on one view: frame time, and the relative MSE of the volume's radiance against a converged Monte
// Carlo image (issue 15).
#ifndef vsBenchPreview_h
#define vsBenchPreview_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchPreview(CLI::App& bench);
}

#endif
