"""Renders the Colin27 MRI through `import vissweep` and checks the image is not
blank and matches the baseline (Testing/Data/Baseline/python_brain.png)."""
import argparse
import os
import sys

import numpy as np
import vtk
import vissweep
from vtkmodules.util.numpy_support import vtk_to_numpy


def render(path):
    reader = vtk.vtkNIFTIImageReader()
    reader.SetFileName(path)
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetSeed(3)
    mapper.SetRenderModeToEmissionAbsorption()
    prop = vtk.vtkVolumeProperty()
    opacity = vtk.vtkPiecewiseFunction()
    for s, a in ((0, 0.0), (40, 0.0), (90, 0.05), (255, 0.3)):
        opacity.AddPoint(s, a)
    color = vtk.vtkColorTransferFunction()
    color.AddRGBPoint(0, 0.0, 0.0, 0.0)
    color.AddRGBPoint(90, 0.9, 0.6, 0.5)
    color.AddRGBPoint(255, 1.0, 1.0, 0.9)
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    ren.SetBackground(0, 0, 0)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(128, 128)
    ren.ResetCamera()
    ren.GetActiveCamera().Elevation(-70)
    win.Render()
    if mapper.GetLastError():
        raise RuntimeError(mapper.GetLastError())
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(grab.GetOutput())
    return image


def render_monte_carlo(path):
    """TwoStep Monte Carlo under a procedural sun: returns (window image, radiance, mapper)."""
    reader = vtk.vtkNIFTIImageReader()
    reader.SetFileName(path)
    shrink = vtk.vtkImageShrink3D()
    shrink.SetInputConnection(reader.GetOutputPort())
    shrink.SetShrinkFactors(2, 2, 2)
    shrink.Update()  # so that ResetCamera sees the volume's bounds
    sun = vissweep.vtkEnvironmentMapSource()
    sun.SetTypeToSunDisk()
    sun.SetSunDirection(0.3, 0.8, 0.5)
    sun.SetSunAngularRadius(3.0)
    sun.SetSunRadiance(200.0, 190.0, 170.0)
    sun.SetSkyColor(0.3, 0.4, 0.6)
    sun.SetOctahedralSize(64)
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    mapper.SetInputConnection(shrink.GetOutputPort())
    mapper.SetEnvironmentConnection(sun.GetOutputPort())
    mapper.SetSamplingStrategyToTwoStep()
    mapper.SetSeed(5)
    mapper.SetSamplesPerFrame(4)
    mapper.SetMaximumSamples(8)
    prop = vtk.vtkVolumeProperty()
    opacity = vtk.vtkPiecewiseFunction()
    for s, a in ((0, 0.0), (40, 0.0), (80, 0.3), (255, 0.6)):
        opacity.AddPoint(s, a)
    prop.SetScalarOpacity(opacity)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(64, 64)
    cam = ren.GetActiveCamera()
    cam.SetViewUp(0, 0, 1)
    cam.SetPosition(0.4, 1.0, 0.25)
    cam.SetFocalPoint(0, 0, 0)
    ren.ResetCamera()
    while not mapper.IsConverged():
        win.Render()
        if mapper.GetLastError():
            raise RuntimeError(mapper.GetLastError())
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(grab.GetOutput())
    return image, mapper.GetRadiance(), mapper


def compare(image, baseline, out):
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputData(image)
    writer.Write()
    if not os.path.exists(baseline):
        print(f"FAIL: no baseline {baseline}; the test image is {out}")
        return False
    png = vtk.vtkPNGReader()
    png.SetFileName(baseline)
    png.Update()
    diff = vtk.vtkImageDifference()
    diff.SetInputData(image)
    diff.SetImageConnection(png.GetOutputPort())
    diff.Update()
    error = diff.GetThresholdedError()
    print(f"thresholded difference to {os.path.basename(baseline)}: {error:.4f}")
    if error > 0.05:
        print(f"FAIL: differs from {baseline}; see {out}")
        return False
    return True


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--data", required=True)
    ap.add_argument("--baseline", required=True)
    ap.add_argument("--output", required=True)
    args = ap.parse_args()

    image = render(args.data)
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    covered = (pixels.max(axis=1) > 10).mean()
    print(f"fraction of pixels covered by the volume: {covered:.3f}, std {pixels.std():.1f}")
    if covered < 0.15 or pixels.std() < 10:
        print("FAIL: the image is (nearly) blank")
        return 1

    if not compare(image, os.path.join(args.baseline, "python_brain.png"),
                   os.path.join(args.output, "python_brain.png")):
        return 1

    # Monte Carlo through the Python API: finite radiance, the samples asked for, the visibility grid.
    mc_image, radiance, mapper = render_monte_carlo(args.data)
    rgb = vtk_to_numpy(radiance.GetPointData().GetArray("Radiance"))
    print(f"Monte Carlo: {mapper.GetAccumulatedSamples()} spp, mean radiance {rgb.mean():.4f}, "
          f"sweeps {mapper.GetLastSweepSeconds():.2f} s")
    if not np.isfinite(rgb).all() or rgb.mean() <= 0 or mapper.GetAccumulatedSamples() != 8:
        print("FAIL: Monte Carlo radiance is not finite, blank, or has the wrong sample count")
        return 1
    grid = mapper.GetVisibilityGrid()
    if grid is None or grid.GetPointData().GetArray("Visibility").GetNumberOfComponents() != 64:
        print("FAIL: no visibility grid from the mapper")
        return 1
    if not compare(mc_image, os.path.join(args.baseline, "python_brain_mc.png"),
                   os.path.join(args.output, "python_brain_mc.png")):
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
