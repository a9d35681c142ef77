#!/usr/bin/env python3
"""Renders the Colin27 brain MRI with VisSweep.

    PYTHONPATH=build xvfb-run -a /usr/bin/python3 Examples/Python/render_brain.py \
        --volume /usr/share/mricron/templates/ch2.nii.gz --output brain.png

With --interactive, opens a window (needs a display) instead of writing a PNG.
"""
import argparse
import time

import vtk
import vissweep


def brain_property():
    """A skin-and-brain transfer function for Colin27 (scalars 0..255)."""
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
    prop.SetScalarOpacityUnitDistance(1.0)
    return prop


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--volume", default="/usr/share/mricron/templates/ch2.nii.gz")
    ap.add_argument("--output", default="brain.png")
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--interactive", action="store_true")
    args = ap.parse_args()

    t = time.perf_counter()
    reader = vtk.vtkNIFTIImageReader()
    reader.SetFileName(args.volume)
    reader.Update()
    print(f"read {args.volume}: {reader.GetOutput().GetDimensions()} in {time.perf_counter() - t:.2f} s")

    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(brain_property())

    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    ren.SetBackground(0.05, 0.05, 0.08)
    win = vtk.vtkRenderWindow()
    win.AddRenderer(ren)
    win.SetSize(args.size, args.size)
    win.SetMultiSamples(0)
    if not args.interactive:
        win.SetOffScreenRendering(1)
    cam = ren.GetActiveCamera()
    cam.SetViewUp(0, 0, 1)
    cam.SetPosition(0.4, 1, 0.25)
    cam.SetFocalPoint(0, 0, 0)
    ren.ResetCamera()
    cam.Azimuth(-30)

    t = time.perf_counter()
    win.Render()
    if mapper.GetLastError():
        raise SystemExit(f"render failed: {mapper.GetLastError()}")
    print(f"rendered {args.size}x{args.size} in {time.perf_counter() - t:.2f} s "
          f"(device {mapper.GetLastDeviceSeconds():.2f} s)")

    if args.interactive:
        iren = vtk.vtkRenderWindowInteractor()
        iren.SetRenderWindow(win)
        iren.Start()
        return
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
