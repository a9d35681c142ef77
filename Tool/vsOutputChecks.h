// vsOutputChecks.h — what `vissweep render` can know about its outputs before it renders, checked
// before it renders (bad input never costs a render, and never writes partial output): every image
// path of every frame and the --json path (writable, not a folder, no two the same), that the render
// mode makes what each format holds, and that the camera sees the volume at all.
#ifndef vsOutputChecks_h
#define vsOutputChecks_h

#include <string>
#include <vector>

namespace vstool
{
struct SceneObjects;

/** Throws std::runtime_error (naming the option and the path) unless every image in `images` (-o,
 *  every frame's name) has a known format and can be written, `json` (empty or "-": none) can be
 *  written, and no two of them name the same file. */
void CheckOutputs(const std::vector<std::string>& images, const std::string& json);

/** Throws std::runtime_error when an output needs what the render mode (the scene file's spelling)
 *  does not make: an .exr holds the radiance, which the ambient-occlusion and emission-absorption
 *  modes do not compute. */
void CheckOutputsForMode(const std::vector<std::string>& images, const std::string& mode);

/** Throws std::runtime_error when the camera sees none of the volume (VTK would cull it, and the
 *  render would accumulate nothing): its bounds lie wholly outside one of the view frustum's planes. */
void CheckVolumeInView(SceneObjects& objects);
}

#endif
