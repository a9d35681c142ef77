/**
 * @class   vtkVisSweepHeadlessWindow
 * @brief   A render window for VisSweep volumes that needs no X display and no OpenGL.
 *
 * VisSweep renders on the Vulkan device; VTK's window only receives the finished image. Debian's
 * VTK opens its render windows on an X display (it has neither EGL nor OSMesa), so a renderer on a
 * headless machine needed an X server (xvfb-run) for nothing but that last step. This window takes
 * the image instead: Render() starts each renderer's frame as vtkRenderer::Render() does (its
 * StartEvent, the camera reset of a renderer that has none yet), clears its viewport to the
 * renderer's background and renders its visible volumes; each vtkVisibilitySweepVolumeMapper draws
 * its window image over it exactly as it does in an OpenGL window (premultiplied RGBA, blended
 * ONE, ONE_MINUS_SRC_ALPHA into 8 bits per channel, rounded as llvmpipe rounds: half to even), so
 * the pixels are those of the OpenGL window, bit for bit in every mode (Render.TestMapperHeadless,
 * Render.TestHeadlessBlend).
 * GetPixelData(), GetRGBACharPixelData() and GetRGBAPixelData() read them back, so that
 * vtkWindowToImageFilter works as with any window:
 *
 *   vtkNew<vtkVisSweepHeadlessWindow> window;   // instead of vtkRenderWindow
 *   window->SetSize(512, 512);
 *   window->AddRenderer(renderer);
 *   window->Render();
 *
 * It draws volumes only: actors, 2D actors, a vtkSkybox and gradient backgrounds are not drawn
 * (a warning says so once), and other mappers draw nothing into it (they need OpenGL). The
 * environment a VisSweep volume shows is painted by the volume itself (EnvironmentAsBackground has
 * no skybox to composite over here). There is no interactor.
 */
#ifndef vtkVisSweepHeadlessWindow_h
#define vtkVisSweepHeadlessWindow_h

#include "vissweepRenderingModule.h"
#include "vtkRenderWindow.h"

#include <vector>

class VISSWEEPRENDERING_EXPORT vtkVisSweepHeadlessWindow : public vtkRenderWindow
{
public:
  static vtkVisSweepHeadlessWindow* New();
  vtkTypeMacro(vtkVisSweepHeadlessWindow, vtkRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Renders every renderer's visible volumes into the window's image (see the class comment). */
  void Render() override;

  /** Blends `rgba` (premultiplied RGBA float, `width` x `height`, rows bottom-up) over the pixels
   *  (x, y) to (x2, y2), ONE, ONE_MINUS_SRC_ALPHA as the OpenGL window's blend, stretched (nearest
   *  pixel) when its size differs. Used by vtkVisibilitySweepVolumeMapper. */
  void BlendPremultiplied(int x, int y, int x2, int y2, const float* rgba, int width, int height);

  ///@{
  /** The window's pixels, rows bottom-up, as vtkRenderWindow's (front/back and right are ignored:
   *  there is one buffer). The pointer versions return new[] arrays the caller deletes. */
  unsigned char* GetPixelData(int x, int y, int x2, int y2, int front, int right = 0) override;
  int GetPixelData(int x, int y, int x2, int y2, int front, vtkUnsignedCharArray* data, int right = 0) override;
  unsigned char* GetRGBACharPixelData(int x, int y, int x2, int y2, int front, int right = 0) override;
  int GetRGBACharPixelData(
    int x, int y, int x2, int y2, int front, vtkUnsignedCharArray* data, int right = 0) override;
  float* GetRGBAPixelData(int x, int y, int x2, int y2, int front, int right = 0) override;
  int GetRGBAPixelData(int x, int y, int x2, int y2, int front, vtkFloatArray* data, int right = 0) override;
  void ReleaseRGBAPixelData(float* data) override;
  ///@}

  /** Nothing to make current, no buffers to swap: there is no OpenGL context. */
  void MakeCurrent() override {}
  bool IsCurrent() override { return true; }
  void Frame() override {}
  const char* ReportCapabilities() override { return "vtkVisSweepHeadlessWindow: VisSweep volumes, no OpenGL"; }
  int SupportsOpenGL() override { return 0; }
  bool InitializeFromCurrentContext() override { return false; }
  int GetDepthBufferSize() override { return 0; }
  int GetColorBufferSizes(int* rgba) override;

protected:
  vtkVisSweepHeadlessWindow();
  ~vtkVisSweepHeadlessWindow() override;

private:
  vtkVisSweepHeadlessWindow(const vtkVisSweepHeadlessWindow&) = delete;
  void operator=(const vtkVisSweepHeadlessWindow&) = delete;

  void Resize();
  bool Clamp(int& x, int& y, int& x2, int& y2) const;
  std::vector<unsigned char> Pixels; // RGBA, 8 bits per channel, rows bottom-up
  int PixelsSize[2] = { 0, 0 };
  bool WarnedActors = false;
};

#endif
