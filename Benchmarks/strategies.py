#!/usr/bin/env python3
"""Samples per second and efficiency of every strategy (and both cell modes) on one scene.

    PYTHONPATH=build xvfb-run -a /usr/bin/python3 Benchmarks/strategies.py [--size 128] [--spp 32]

For each configuration: device-independent wall time per frame after warm-up, paths per
second, the mean per-pixel variance of one sample (luminance), and the efficiency
1 / (variance x seconds per sample) relative to Uniform -- the error reached in equal time.
Scene: the Colin27 MRI with the benchmark skin TF under the sunrise HDRI.
"""
import argparse
import json
import os
import time

import numpy as np
import vtk
import vissweep
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--volume", default="/usr/share/mricron/templates/ch2.nii.gz")
    ap.add_argument("--environment", default=os.path.join(HERE, "..", "Data", "envmaps", "sunrise.exr"))
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--spp", type=int, default=32)
    ap.add_argument("--json")
    args = ap.parse_args()

    reader = vtk.vtkNIFTIImageReader()
    reader.SetFileName(args.volume)
    reader.Update()
    light = vissweep.vtkEnvironmentMapReader()
    light.SetFileName(args.environment)
    light.SetRotationDegrees(200)
    prop = vtk.vtkVolumeProperty()
    opacity = vtk.vtkPiecewiseFunction()
    for s, a in ((0, 0.0), (40, 0.0), (80, 0.3), (255, 0.6)):
        opacity.AddPoint(s, a)
    color = vtk.vtkColorTransferFunction()
    color.AddRGBPoint(0, 0.9, 0.7, 0.6)
    color.AddRGBPoint(255, 1.0, 0.95, 0.9)
    prop.SetScalarOpacity(opacity)
    prop.SetColor(color)
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetEnvironmentConnection(light.GetOutputPort())
    mapper.SetEnvironmentVisible(False)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(args.size, args.size)
    cam = ren.GetActiveCamera()
    cam.SetViewUp(0, 0, 1)
    cam.SetPosition(0.4, 1.0, 0.25)
    cam.SetFocalPoint(0, 0, 0)
    ren.ResetCamera()

    configs = [("Uniform", 0), ("Environment", 0), ("Visibility", 1), ("Combined", 0), ("Combined", 1),
               ("TwoStep", 0), ("TwoStep", 1)]
    results = []
    for name, cell in configs:
        getattr(mapper, "SetSamplingStrategyTo" + name)()
        mapper.SetCellMode(cell)
        mapper.SetSamplesPerFrame(1)
        mapper.SetMaximumSamples(1 << 30)
        win.Render()  # sweeps and pipeline compilation happen here, not in the timing
        mapper.SetSamplesPerFrame(args.spp)
        mapper.SetSeed(mapper.GetSeed() + 1)  # restart accumulation
        t = time.perf_counter()
        win.Render()
        seconds = time.perf_counter() - t
        rad = mapper.GetRadiance(True)
        var = vtk_to_numpy(rad.GetPointData().GetArray("Variance"))[:, :3].mean(axis=1)
        alpha = vtk_to_numpy(rad.GetPointData().GetArray("Alpha"))
        covered = alpha > 0.05
        v = float(var[covered].mean())
        per_sample = seconds / args.spp
        results.append({"strategy": name, "cell_mode": "stochastic" if cell else "trilinear",
                        "seconds_per_frame_sample": per_sample,
                        "paths_per_second": args.size * args.size / per_sample,
                        "variance": v, "efficiency": 1.0 / (v * per_sample)})
    base = results[0]
    print(f"{'strategy':<12} {'cells':<10} {'paths/s':>10} {'vs uniform':>10} {'variance':>10} {'efficiency':>10}")
    for r in results:
        print(f"{r['strategy']:<12} {r['cell_mode']:<10} {r['paths_per_second']:>10.0f} "
              f"{base['seconds_per_frame_sample'] / r['seconds_per_frame_sample']:>10.2f} {r['variance']:>10.4f} "
              f"{r['efficiency'] / base['efficiency']:>10.2f}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=2)


if __name__ == "__main__":
    main()
