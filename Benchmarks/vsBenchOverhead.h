// vsBenchOverhead.h — `vissweep bench overhead [SCENE]`: what each sampling strategy
// costs per sample and buys per unit of time, on one scene and this machine; and the
// render kernel's volume-read rate against the device's plain ray-march rate.
#ifndef vsBenchOverhead_h
#define vsBenchOverhead_h

namespace CLI
{
class App;
}

namespace vstool
{
void AddBenchOverhead(CLI::App& bench);
}

#endif
