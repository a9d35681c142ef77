#!/usr/bin/env python3
"""A contact sheet of mri_sunrise (Colin27, Benchmarks/scenes/mri_sunrise.json's transfer function, camera
and sunrise sky): VisSweep's Monte Carlo mode volumetric (ShadeOff), blended (ShadeOn,
VolumetricScatteringBlending 1) and surface (ShadeOn, blending 0), each beside VTK's
vtkGPUVolumeRayCastMapper with shading on (the same property; VTK's headlight), on black
(docs/gallery/shading_sheet.png, docs/benchmarks.md). Each tile's label stands in a strip below it. From the
repository's root:

    PYTHONPATH=build xvfb-run -a /usr/bin/python3 Benchmarks/contact_sheet_shading.py \\
        --output docs/gallery/shading_sheet.png --size 160 --spp 128
"""
import argparse
import os
import sys
import time

import numpy as np
import vtk
import vissweep
from vtkmodules.util.numpy_support import vtk_to_numpy

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def volume_property(shade):
    """mri_sunrise.json's transfer function; VTK's default Ambient, Diffuse, Specular, SpecularPower."""
    opacity = vtk.vtkPiecewiseFunction()
    for s, a in ((0, 0.0), (40, 0.0), (80, 0.3), (255, 0.6)):
        opacity.AddPoint(s, a)
    color = vtk.vtkColorTransferFunction()
    for s, r, g, b in ((0, 0.85, 0.62, 0.52), (80, 0.9, 0.68, 0.58), (150, 0.95, 0.82, 0.75), (255, 1.0, 0.93, 0.88)):
        color.AddRGBPoint(s, r, g, b)
    prop = vtk.vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(1.0)
    prop.SetInterpolationTypeToLinear()
    prop.SetShade(1 if shade else 0)
    return prop


def grab_window(win, width, height):
    """The window's rgb as drawn, top row first."""
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ShouldRerenderOff()
    grab.Update()
    img = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3]
    return img[::-1]


LABEL_HEIGHT = 30  # two lines of 11-point text
_label_window = {}  # one window for every label, kept open (a window per label made xvfb's server reset)


def label_strip(label, width):
    """`label` (one or two lines) in white on black, a strip `width` wide under a tile: the label never
    covers the volume and never runs past the tile's edge (the lines are short enough for 144 pixels and more)."""
    if not _label_window:
        ren = vtk.vtkRenderer()
        ren.SetBackground(0, 0, 0)
        text = vtk.vtkTextActor()
        text.GetTextProperty().SetFontSize(11)
        text.GetTextProperty().SetColor(1, 1, 1)
        text.GetTextProperty().SetJustificationToCentered()
        text.GetTextProperty().SetVerticalJustificationToCentered()
        ren.AddActor2D(text)
        win = vtk.vtkRenderWindow()
        win.SetOffScreenRendering(1)
        win.SetMultiSamples(0)
        win.AddRenderer(ren)
        _label_window.update(text=text, win=win)
    text, win = _label_window["text"], _label_window["win"]
    text.SetInput(label)
    text.SetPosition(width / 2.0, LABEL_HEIGHT / 2.0)
    win.SetSize(width, LABEL_HEIGHT)
    win.Render()
    return grab_window(win, width, LABEL_HEIGHT)


def render(reader, mapper, shade, size, label):
    """The tile: the volume rendered at size x size, its label in a strip below it."""
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(volume_property(shade))
    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    ren.SetBackground(0, 0, 0)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.SetSize(size, size)
    win.AddRenderer(ren)
    cam = ren.GetActiveCamera()
    cam.SetPosition(-50, 500, 115)
    cam.SetFocalPoint(90, 125, 68)
    cam.SetViewUp(0, 0, 1)
    cam.SetViewAngle(30)
    ren.ResetCameraClippingRange()
    t = time.perf_counter()
    if isinstance(mapper, vissweep.vtkVisibilitySweepVolumeMapper):
        spp = mapper.RenderUntilConverged(win)
        if mapper.GetLastError():
            sys.exit("render failed: " + mapper.GetLastError())
        what = "%d spp" % spp
    else:
        win.Render()
        what = "one render"
    print("%-40s %s in %.1f s" % (label.replace("\n", " "), what, time.perf_counter() - t), flush=True)
    return np.concatenate([grab_window(win, size, size), label_strip(label, size)], axis=0)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--volume", default="/usr/share/mricron/templates/ch2.nii.gz")
    ap.add_argument("--environment", default=os.path.join(ROOT, "Data", "envmaps", "sunrise.exr"))
    ap.add_argument("--output", default="shading_sheet.png")
    ap.add_argument("--size", type=int, default=144, help="each tile's side in pixels")
    ap.add_argument("--spp", type=int, default=64)
    args = ap.parse_args()

    reader = vtk.vtkNIFTIImageReader()
    reader.SetFileName(args.volume)
    sky = vissweep.vtkEnvironmentMapReader()
    sky.SetFileName(args.environment)
    sky.SetRotationDegrees(96)

    gpu = vtk.vtkGPUVolumeRayCastMapper()
    gpu.SetInputConnection(reader.GetOutputPort())
    theirs = render(reader, gpu, True, args.size, "VTK GPU ray cast\n(ShadeOn)")
    rows = []
    for label, shade, blending in (("volumetric\n(ShadeOff)", False, 0.0),
                                   ("blended\n(ShadeOn, blending 1)", True, 1.0),
                                   ("surface\n(ShadeOn, blending 0)", True, 0.0)):
        mapper = vissweep.vtkVisibilitySweepVolumeMapper()
        mapper.SetInputConnection(reader.GetOutputPort())
        mapper.SetEnvironmentConnection(sky.GetOutputPort())
        mapper.EnvironmentVisibleOff()  # black behind both, so that the volumes compare
        mapper.SetSamplingStrategyToEnvironment()
        mapper.SetVolumetricScatteringBlending(blending)
        mapper.SetMaximumSamples(args.spp)
        mapper.SetSamplesPerFrame(8)
        mine = render(reader, mapper, shade, args.size, "VisSweep " + label)
        rows.append(np.concatenate([mine, theirs], axis=1))
    sheet = np.ascontiguousarray(np.concatenate(rows, axis=0).astype(np.uint8))
    try:
        from PIL import Image  # a palette PNG keeps the sheet small for the docs
        Image.fromarray(sheet).quantize(colors=255, dither=Image.Dither.NONE).save(args.output, optimize=True)
    except ImportError:
        image = vtk.vtkImageData()
        h, w, _ = sheet.shape
        image.SetDimensions(w, h, 1)
        from vtkmodules.util.numpy_support import numpy_to_vtk
        image.GetPointData().SetScalars(numpy_to_vtk(sheet[::-1].reshape(-1, 3), deep=True))
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(args.output)
        writer.SetInputData(image)
        writer.Write()
    print("wrote %s (%d x %d, %.0f KiB)" % (args.output, sheet.shape[1], sheet.shape[0],
                                            os.path.getsize(args.output) / 1024.0))


if __name__ == "__main__":
    main()
