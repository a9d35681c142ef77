"""Coming from vtkGPUVolumeRayCastMapper (issue 38, item 5), as a new user does it: a small pipeline
rendered with VTK's GPU mapper (a gradient background, shading, a sample distance, automatic sample
distances off), then the same pipeline with vtkVisibilitySweepVolumeMapper swapped in and nothing
else changed but the render call. Checks that
- the renderer's background (the gradient) is kept where no environment is given: the window's
  corners are those of the GPU mapper's image (they were the white sky), while the white sky still
  lights the volume (the ball is bright, its radiance that of the volume lit by radiance 1);
- a connected environment is shown instead of the background;
- RenderUntilConverged renders to MaximumSamples in one call, or to a time budget;
- the GPU mapper's settings that mean something else here (SampleDistance in the Monte Carlo mode,
  AutoAdjustSampleDistances off) are warned about once each, not at every frame.
"""
import argparse
import sys
import time

import numpy as np
import vtk
import vissweep
from vtkmodules.util.numpy_support import vtk_to_numpy

BOTTOM, TOP = (0.1, 0.2, 0.4), (0.8, 0.8, 0.9)
SIZE = 64


def pipeline(mapper):
    """The user's pipeline: every line but the mapper's class is the same for both mappers."""
    ball = vtk.vtkImageEllipsoidSource()
    ball.SetWholeExtent(0, 23, 0, 23, 0, 23)
    ball.SetCenter(11.5, 11.5, 11.5)
    ball.SetRadius(9, 9, 9)
    ball.SetInValue(255)
    ball.SetOutValue(0)
    opacity = vtk.vtkPiecewiseFunction()
    opacity.AddPoint(0, 0.0)
    opacity.AddPoint(255, 0.9)
    color = vtk.vtkColorTransferFunction()
    color.AddRGBPoint(0, 0.9, 0.8, 0.7)
    color.AddRGBPoint(255, 0.9, 0.8, 0.7)
    prop = vtk.vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()
    mapper.SetInputConnection(ball.GetOutputPort())
    mapper.SetBlendModeToComposite()
    mapper.SetSampleDistance(0.5)
    mapper.AutoAdjustSampleDistancesOff()
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    ren.SetBackground(*BOTTOM)
    ren.SetBackground2(*TOP)
    ren.GradientBackgroundOn()
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.SetSize(SIZE, SIZE)
    win.AddRenderer(ren)
    ren.ResetCamera()
    return win


def pixels(win):
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ShouldRerenderOff()  # a re-render would add samples
    grab.Update()
    a = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(np.float64)
    return a.reshape(SIZE, SIZE, -1)[:, :, :3]


def corners(img):
    k = 6
    return np.concatenate([img[:k, :k], img[:k, -k:], img[-k:, :k], img[-k:, -k:]]).reshape(-1, 3)


failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--data")
    parser.add_argument("--baseline")
    parser.add_argument("--output")
    parser.parse_args()

    # VTK's GPU mapper: the reference background.
    gpu_win = pipeline(vtk.vtkGPUVolumeRayCastMapper())
    gpu_win.Render()
    gpu = pixels(gpu_win)
    check(np.abs(corners(gpu) - corners(gpu).mean(axis=0)).max() > 20,
          "the GPU mapper's corners show the gradient (top and bottom differ)")

    # The warnings VTK would print, captured: the output window's text.
    out = vtk.vtkStringOutputWindow()
    vtk.vtkOutputWindow.SetInstance(out)

    # The swap: the same pipeline, VisSweep's mapper, one call to converge.
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    win = pipeline(mapper)
    mapper.SetSamplingStrategyToEnvironment()
    mapper.SetMaximumSamples(16)
    mapper.SetSamplesPerFrame(2)
    spp = mapper.RenderUntilConverged(win)
    check(not mapper.GetLastError(), "renders: %s" % mapper.GetLastError())
    check(spp == 16 and mapper.IsConverged() and mapper.GetAccumulatedSamples() == 16,
          "RenderUntilConverged renders to MaximumSamples in one call (%d spp)" % spp)
    check(not mapper.GetShowsEnvironment(), "no environment connected: none is shown")
    img = pixels(win)
    diff = np.abs(corners(img) - corners(gpu)).max()
    print("corners: largest difference from the GPU mapper's image %.1f / 255" % diff)
    check(diff <= 3.0, "the renderer's gradient background is kept (the corners are the GPU mapper's)")
    centre = img[SIZE // 2 - 4:SIZE // 2 + 4, SIZE // 2 - 4:SIZE // 2 + 4].mean(axis=(0, 1))
    print("centre of the ball:", centre)
    check(centre.mean() > 80 and np.abs(centre - np.array(BOTTOM) * 255).max() > 40,
          "the ball is lit by the default white sky (bright, not the background)")
    radiance = vtk_to_numpy(mapper.GetRadiance().GetPointData().GetArray("Radiance"))
    check(radiance.max() > 0.3, "the radiance is that of a lit volume (max %.3f)" % radiance.max())

    text = out.GetOutput()
    n_step = text.count("SampleDistance is not a step")
    n_auto = text.count("AutoAdjustSampleDistances off")
    print("warnings over 8 renders: SampleDistance %d, AutoAdjustSampleDistances %d" % (n_step, n_auto))
    check(n_step == 1, "SampleDistance in the Monte Carlo mode is warned about once")
    check(n_auto == 1, "AutoAdjustSampleDistances off is warned about once")

    # A connected environment is shown instead (a green sky).
    sky = vissweep.vtkEnvironmentMapSource()
    sky.SetColor(0.1, 0.8, 0.1)
    mapper.SetEnvironmentConnection(sky.GetOutputPort())
    mapper.SetMaximumSamples(4)
    mapper.RenderUntilConverged(win)
    win.Render()  # the skybox is drawn from the renderer's second frame with it
    green = corners(pixels(win)).mean(axis=0)
    print("corners with a green environment:", green)
    check(mapper.GetShowsEnvironment() and green[1] > green[0] + 60 and green[1] > green[2] + 60,
          "a connected environment is shown behind the volume")

    # A time budget, in one call.
    mapper.SetMaximumSamples(1 << 20)
    mapper.SetSamplesPerFrame(1)
    mapper.SetSeed(7)  # restart
    start = time.monotonic()
    spp = mapper.RenderUntilConverged(win, 1.0)
    elapsed = time.monotonic() - start
    print("time budget 1 s: %d spp in %.2f s" % (spp, elapsed))
    check(0 < spp < (1 << 20) and not mapper.IsConverged(), "a time budget stops before MaximumSamples")
    check(elapsed < 3.0, "a time budget of 1 s ends within a frame of it (%.2f s, loaded machine)" % elapsed)

    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
