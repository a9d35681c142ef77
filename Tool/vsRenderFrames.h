// vsRenderFrames.h — `vissweep render SCENE.json --frames A:B -o OUT...`: renders time steps A..B
// of the scene's volume "files" sequence, one image per step per output, with one mapper for the
// whole range so that the visibility grid is updated lazily between steps (render.update_scheme).
// Prints and records (--json) per-frame update time (upload, majorants, sweeps), render time and spp.
#ifndef vsRenderFrames_h
#define vsRenderFrames_h

#include <string>

namespace vstool
{
struct RenderOptions;
struct Scene;
struct SceneObjects;

/** An inclusive range of time steps. */
struct FrameRange
{
  int First = 0;
  int Last = 0;
};

/** Parses "A:B" (or "A" for one step) against a sequence of `steps` time steps; throws
 *  std::runtime_error naming --frames when malformed, reversed or out of range. */
FrameRange ParseFrameRange(const std::string& text, int steps);

/** The file of `frame` for output `out`: a printf pattern with one integer conversion
 *  ("smoke_%04d.png") is formatted; otherwise _NNNN goes before the extension ("a.png" ->
 *  "a_0003.png"). Throws std::runtime_error for a pattern with other '%' conversions. */
std::string FrameOutputName(const std::string& out, int frame);

/** Makes time step `step` of the scene's volume sequence the mapper's input (a new data object,
 *  so the mapper uploads it; same grid under the reader's UnionBounds, so updates may be lazy). */
void ShowTimeStep(SceneObjects& objects, const Scene& scene, int step);

/** Runs the command; returns the exit status (0). Throws std::runtime_error on errors. */
int RunFrames(const RenderOptions& options);
}

#endif
