// vsBenchLightVolume.h — `vissweep bench lightvolume SCENE.json`: the light volume (vs::LightVolume)
// rebuilt after each rotation of the scene's environment, at the renderer's default grid.
#ifndef vsBenchLightVolume_h
#define vsBenchLightVolume_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchLightVolume(CLI::App& bench);
}

#endif
