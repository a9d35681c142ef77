"""Renders the Colin27 MRI through `import vissweep` and checks the image is not
blank and matches the baseline (Testing/Data/Baseline/python_brain.png)."""
import argparse
import os
import sys

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

    out = os.path.join(args.output, "python_brain.png")
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(out)
    writer.SetInputData(image)
    writer.Write()
    baseline = os.path.join(args.baseline, "python_brain.png")
    if not os.path.exists(baseline):
        print(f"FAIL: no baseline {baseline}; the test image is {out}")
        return 1
    png = vtk.vtkPNGReader()
    png.SetFileName(baseline)
    png.Update()
    diff = vtk.vtkImageDifference()
    diff.SetInputData(image)
    diff.SetImageConnection(png.GetOutputPort())
    diff.Update()
    error = diff.GetThresholdedError()
    print(f"thresholded difference to the baseline: {error:.4f}")
    if error > 0.05:
        print(f"FAIL: differs from {baseline}; see {out}")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
