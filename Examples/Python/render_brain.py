#!/usr/bin/env python3
"""Renders the Colin27 brain MRI with VisSweep: unbiased Monte Carlo single
scattering under a real HDR environment (sunrise), TwoStep sampling (environment x
visibility), progressive.

    PYTHONPATH=build xvfb-run -a /usr/bin/python3 Examples/Python/render_brain.py \
        --volume /usr/share/mricron/templates/ch2.nii.gz --output brain.png

With --interactive, opens a window (needs a display) that keeps refining while the
view is still; --emission-absorption renders the classic ray-cast image instead.
"""
import os
import argparse
import sys
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
    prop.SetInterpolationTypeToLinear()  # smooth for an MRI (VTK defaults to nearest, for label maps)
    prop.SetScalarOpacityUnitDistance(1.0)
    return prop


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--volume", default="/usr/share/mricron/templates/ch2.nii.gz")
    ap.add_argument("--output", default="brain.png")
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--spp", type=int, default=64, help="samples per pixel")
    ap.add_argument("--environment", default=os.path.join(os.path.dirname(__file__), "..", "..", "Data",
                                                          "envmaps", "sunrise.exr"))
    ap.add_argument("--strategy", default="TwoStep",
                    choices=["Uniform", "Environment", "Visibility", "Combined", "TwoStep", "Auto"])
    ap.add_argument("--rotation", type=float, default=200.0, help="environment rotation about the up axis, degrees")
    ap.add_argument("--seconds", type=float, default=0.0,
                    help="stop refining before a frame that would end after this many seconds, even below "
                         "--spp (0: no limit)")
    ap.add_argument("--preview-first", action="store_true",
                    help="start from the noise-free preview and hand over to the estimate as it converges "
                         "(the image shown blends the two by their measured errors; see README)")
    ap.add_argument("--denoise", action="store_true",
                    help="show (and write) the estimate through the display's edge-aware filter guided by the "
                         "preview (DisplayDenoise; GetRadiance() stays the unbiased estimate; see README)")
    ap.add_argument("--emission-absorption", action="store_true")
    ap.add_argument("--interactive", action="store_true")
    args = ap.parse_args()

    t = time.perf_counter()
    reader = vtk.vtkNIFTIImageReader()
    reader.SetFileName(args.volume)
    try:
        image = vissweep.read_checked(reader)  # a truncated or corrupt file is an error, not a partial image
    except RuntimeError as e:
        raise SystemExit(f"cannot read the volume: {e}")
    print(f"read {args.volume}: {image.GetDimensions()} in {time.perf_counter() - t:.2f} s")

    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    mapper.SetInputData(image)
    if args.emission_absorption:
        mapper.SetRenderModeToEmissionAbsorption()
    else:
        environment = vissweep.vtkEnvironmentMapReader()
        environment.SetFileName(args.environment)
        environment.SetRotationDegrees(args.rotation)
        mapper.SetEnvironmentConnection(environment.GetOutputPort())
        getattr(mapper, "SetSamplingStrategyTo" + args.strategy)()
        mapper.SetSamplesPerFrame(8)
        mapper.SetMaximumSamples(args.spp)
        mapper.SetDisplayDenoise(args.denoise)
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

    if args.interactive:
        iren = vtk.vtkRenderWindowInteractor()
        iren.SetRenderWindow(win)
        iren.Initialize()
        # Keep refining while the view is still: a repeating timer renders until converged.
        def refine(obj, event):
            # after an error, only interaction renders again (no spinning on a failed render)
            if not args.emission_absorption and not mapper.IsConverged() and not mapper.GetLastError():
                win.Render()
        iren.AddObserver("TimerEvent", refine)
        iren.CreateRepeatingTimer(30)
        iren.Start()
        return

    t = time.perf_counter()
    if args.preview_first and not args.emission_absorption:
        # One frame as while the user drags: the preview (the visibility grid, its light volume and a
        # deterministic march); the still frames after it hand over from it to the estimate.
        win.SetDesiredUpdateRate(15.0)
        win.Render()
        if mapper.GetLastError():
            raise SystemExit(f"render failed: {mapper.GetLastError()}")
        print(f"preview in {time.perf_counter() - t:.2f} s")
        win.SetDesiredUpdateRate(0.0001)
    first = True
    # Progress: one line redrawn in place on a terminal; whole lines in a log or a pipe.
    terminal = sys.stdout.isatty()
    redrawn = False
    frame_seconds = 0.0
    while True:
        frame_start = time.perf_counter()
        if args.seconds > 0:
            # The deadline, so that Auto sweeps only what can pay for itself before it.
            mapper.SetRemainingTimeBudget(max(1e-3, args.seconds - (frame_start - t)))
        win.Render()
        frame_seconds = time.perf_counter() - frame_start
        if mapper.GetLastError():
            raise SystemExit(f"render failed: {mapper.GetLastError()}")
        if first and not args.emission_absorption:
            print(f"visibility sweeps: {mapper.GetLastSweepSeconds():.2f} s (device)")
            first = False
        if args.emission_absorption or mapper.IsConverged():
            break
        # Within the budget: no frame that would end after it (a frame of 8 samples takes seconds).
        if args.seconds > 0 and time.perf_counter() - t + frame_seconds > args.seconds:
            break
        progress = f"{mapper.GetAccumulatedSamples()}/{args.spp} samples per pixel"
        if terminal:
            print("\r" + progress, end="", flush=True)
            redrawn = True
        else:
            print(progress, flush=True)
    seconds = time.perf_counter() - t
    if redrawn:
        print()  # end the line redrawn in place
    if args.emission_absorption:
        print(f"rendered {args.size}x{args.size} in {seconds:.2f} s")
    else:
        share = mapper.GetLastPreviewShare()
        shown = (f", shown blended with the preview (its share {share:.2f})" if share > 0
                 else (", the estimate alone (past the hand-over from the preview)" if args.preview_first else ""))
        if mapper.GetLastDisplayDenoised():
            shown += ", through the display filter guided by the preview (--denoise)"
        print(f"rendered {args.size}x{args.size}: {mapper.GetAccumulatedSamples()} spp "
              f"({mapper.GetEffectiveStrategyAsString()}) in {seconds:.2f} s{shown}")
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
