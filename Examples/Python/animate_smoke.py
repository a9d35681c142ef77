#!/usr/bin/env python3
"""Renders the Mantaflow smoke sequence (Data/smoke: 12 time steps, 41x41x62 voxels) under
the CC0 city HDRI as numbered PNG frames, updating the visibility grid lazily between time
steps (von Radziewsky et al. 2017, Sec. 9), and prints each frame's update time (upload, majorants, sweeps)
and render time.

    PYTHONPATH=build xvfb-run -a /usr/bin/python3 Examples/Python/animate_smoke.py \\
        --output-dir smoke_frames --scheme RoundRobin --spp 64

One mapper renders the whole sequence: on each new time step (same grid, new data) it
re-sweeps only the directions the update scheme picks (RoundRobin: the next
--directions-per-frame directions of the bit-reversed Morton order), recomputes the majorants
and restarts accumulation. The image stays unbiased whatever the staleness of the visibility.
"""
import argparse
import os
import time

import vtk
import vissweep

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "Data")
SCHEMES = ["Full", "RoundRobin", "EnvironmentGuided", "Static"]


def smoke_property():
    """Density 0..1 to opacity 0..0.95 per 0.25 world units (VTK's convention), albedo 0.9."""
    prop = vtk.vtkVolumeProperty()
    opacity = vtk.vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(1.0, 0.95)
    color = vtk.vtkColorTransferFunction()
    color.AddRGBPoint(0.0, 0.9, 0.9, 0.9)
    color.AddRGBPoint(1.0, 0.9, 0.9, 0.9)
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    prop.SetScalarOpacityUnitDistance(0.25)
    prop.SetInterpolationTypeToLinear()
    return prop


def smoke_reader(folder):
    reader = vissweep.vtkOpenVDBVolumeReader()
    reader.SetFilePattern(os.path.join(folder, "smoke_%04d.vdb"))
    reader.SetFileIndexRange(4, 48)
    reader.SetFileIndexIncrement(4)
    reader.SetGridName("density")
    reader.UpdateInformation()  # every step covers the union of the steps' bounds (UnionBounds)
    if reader.GetNumberOfTimeSteps() < 1:
        raise SystemExit(f"no smoke files in {folder}")
    return reader


def read_step(reader, step):
    """Time step `step` as its own vtkImageData (a new data object: the mapper uploads it)."""
    reader.UpdateTimeStep(float(step))
    if reader.GetOutput().GetNumberOfPoints() == 0:  # the reader reported why (vtkErrorMacro)
        raise SystemExit(f"cannot read time step {step} of the smoke sequence")
    image = vtk.vtkImageData()
    image.ShallowCopy(reader.GetOutput())
    return image


def parse_frames(text, steps):
    first, _, last = text.partition(":")
    first, last = int(first), int(last or first)
    if not 0 <= first <= last < steps:
        raise SystemExit(f"--frames {text}: the sequence has time steps 0..{steps - 1}")
    return first, last


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--smoke", default=os.path.join(DATA, "smoke"), help="folder of smoke_0004.vdb ... smoke_0048.vdb")
    ap.add_argument("--environment", default=os.path.join(DATA, "envmaps", "city.exr"))
    ap.add_argument("--output-dir", default="smoke_frames")
    ap.add_argument("--frames", default="0:11", help="time steps A:B (inclusive), of 0..11")
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=64, help="samples per pixel per frame")
    ap.add_argument("--scheme", default="RoundRobin", choices=SCHEMES)
    ap.add_argument("--directions-per-frame", type=int, default=4)
    ap.add_argument("--static-interval", type=int, default=16)
    args = ap.parse_args()

    reader = smoke_reader(args.smoke)
    first, last = parse_frames(args.frames, reader.GetNumberOfTimeSteps())
    os.makedirs(args.output_dir, exist_ok=True)

    environment = vissweep.vtkEnvironmentMapReader()
    environment.SetFileName(args.environment)
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    mapper.SetEnvironmentConnection(environment.GetOutputPort())
    mapper.SetSamplingStrategyToTwoStep()
    getattr(mapper, "SetUpdateSchemeTo" + args.scheme)()
    mapper.SetDirectionsPerFrame(args.directions_per_frame)
    mapper.SetStaticInterval(args.static_interval)
    mapper.SetSamplesPerFrame(min(16, args.spp))
    mapper.SetMaximumSamples(args.spp)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(smoke_property())

    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(args.size, args.size)
    cam = ren.GetActiveCamera()
    cam.SetPosition(1.0, -5.5, 1.6)
    cam.SetFocalPoint(1.0, 1.0, 1.45)
    cam.SetViewUp(0, 0, 1)
    cam.SetViewAngle(30)

    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.ShouldRerenderOff()  # a re-render would add samples
    writer = vtk.vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())

    print(f"{args.scheme} updates, {args.directions_per_frame} directions per frame, {args.spp} spp, "
          f"{args.size}x{args.size}, time steps {first}..{last}")
    for step in range(first, last + 1):
        t = time.perf_counter()
        mapper.SetInputData(read_step(reader, step))
        read = time.perf_counter() - t
        t = time.perf_counter()
        win.Render()  # the first render of a step brings the device up to date
        if mapper.GetLastError():
            raise SystemExit(f"render failed: {mapper.GetLastError()}")
        update = mapper.GetLastUpdateSeconds()
        directions = mapper.GetDirectionsUpdatedLastFrame()
        sweeps = mapper.GetLastFrameSweepSeconds()
        while not mapper.IsConverged():
            win.Render()
            if mapper.GetLastError():
                raise SystemExit(f"render failed: {mapper.GetLastError()}")
        render = time.perf_counter() - t - update
        grab.Modified()
        path = os.path.join(args.output_dir, f"frame_{step:04d}.png")
        writer.SetFileName(path)
        writer.Write()
        print(f"frame {step:2d}: read {read:.3f} s, update {update:.3f} s ({directions:2d} directions swept, "
              f"sweeps {sweeps:.3f} s device), render {render:.2f} s "
              f"({mapper.GetAccumulatedSamples()} spp) -> {path}", flush=True)


if __name__ == "__main__":
    main()
