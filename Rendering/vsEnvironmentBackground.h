// vsEnvironmentBackground.h — the visible environment as the renderer's background (issue 14).
// A VisSweep volume that shows the environment (EnvironmentVisible and EnvironmentAsBackground on,
// the Monte Carlo composite) no longer paints it with its own image, which covered what the renderer
// drew before the volume (translucent actors, other volumes). The environment is a vtkSkybox instead,
// the renderer's background, drawn before everything; the volumes composite over it.
//
// The skybox is managed per renderer at the renderer's StartEvent (every window render, tile and
// selection pass), before the renderer collects its props, so it is drawn in the frame that decides
// it: added (an unpickable vtkSkybox of a vtkEnvironmentMapBackground with the mapper's environment and
// display settings) while a visible volume's VisSweep mapper wants it, removed when none does (the
// volume left, its mapper changed, EnvironmentVisible or EnvironmentAsBackground turned off). A
// visible vtkSkybox the user added is the background: none is added then. A renderer is observed from
// the first frame a mapper renders in it, so the environment becomes the background from its second
// frame on (the first is drawn as before: the volume paints the environment).
#ifndef vsEnvironmentBackground_h
#define vsEnvironmentBackground_h

class vtkRenderer;
class vtkSkybox;

namespace vs
{
class EnvironmentBackground
{
public:
  /** Starts managing `ren`'s background (from its next frame on); idempotent. */
  static void Observe(vtkRenderer* ren);
  /** Whether `ren`'s current frame has a skybox background (the managed one or the user's own),
   *  drawn in its opaque pass, before every volume. */
  static bool InFrame(vtkRenderer* ren);
  /** The skybox managed for `ren` while it is in the renderer, else nullptr (for tests). */
  static vtkSkybox* ManagedSkybox(vtkRenderer* ren);
  /** Renderers observed (deleted renderers are forgotten). */
  static int ObservedRenderers();
};
}

#endif
