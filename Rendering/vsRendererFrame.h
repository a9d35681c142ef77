// vsRendererFrame.h — which VisSweep volume of a renderer's frame shows the visible environment.
// With the environment visible, a volume's camera rays that leave it see the environment at full
// opacity, so a second VisSweep volume drawn the same way painted its environment over the first
// (issue 14). Only the first VisSweep volume drawn in a renderer's frame claims the environment;
// the volumes drawn after it in the same frame are transparent where they are empty and composite
// over it. A frame starts at the renderer's StartEvent (vtkRenderer::Render: every window render,
// every tile of a vtkWindowToImageFilter and every selection pass). With the environment as the
// renderer's background (vsEnvironmentBackground.h) nobody paints it and claims decide only the
// frames without a skybox yet (a renderer's first) and volumes with EnvironmentAsBackground off.
#ifndef vsRendererFrame_h
#define vsRendererFrame_h

class vtkRenderer;

namespace vs
{
class RendererFrame
{
public:
  /** True when `owner` is the first to claim `ren`'s current frame (or claimed it already in this
   *  frame: a mapper may draw several times in one frame); false for every other owner until the
   *  renderer's next frame. */
  static bool Claim(vtkRenderer* ren, const void* owner);
  /** Forgets `owner`'s claims (a mapper going away), so that a new object at its address does
   *  not inherit them. */
  static void Forget(const void* owner);
  /** Renderers observed (for tests: deleted renderers are forgotten). */
  static int ObservedRenderers();
};
}

#endif
