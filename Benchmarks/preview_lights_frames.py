#!/usr/bin/env python3
"""Issue 38 item 4: the preview's drag frames with VTK's lights and the surface lobe. Full ch2 under the
sunrise HDRI at 512^2 (the README's transfer function), the Monte Carlo mode's preview while dragging
(desired update rate 15, a 2-degree azimuth per frame): no light, a directional key light (intensity 3),
the key light with ShadeOn, ShadeOn alone. The configurations take turns (6 rounds of 1 + 3 frames each),
so that a loaded machine slows them alike; a round's first frame builds the light volume again when the
lights changed (reported apart). Prints the median wall time of Render() per configuration.

    PYTHONPATH=build LP_NUM_THREADS=2 xvfb-run -a /usr/bin/python3 Benchmarks/preview_lights_frames.py

(--size and --rounds make a quick check of the script itself: the figures are at the defaults.)
"""
import argparse
import os
import statistics
import sys
import time

import vtk
import vissweep

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("--size", type=int, default=512, help="window width and height (default 512)")
ap.add_argument("--rounds", type=int, default=6, help="rounds of 1 + 3 frames per configuration (default 6)")
args = ap.parse_args()
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(root, "Examples", "Python"))
from render_brain import brain_property  # noqa: E402  the README's transfer function, written once there

reader = vtk.vtkNIFTIImageReader()
reader.SetFileName("/usr/share/mricron/templates/ch2.nii.gz")
env = vissweep.vtkEnvironmentMapReader()
env.SetFileName(os.path.join(root, "Data", "envmaps", "sunrise.exr"))
prop = brain_property()
mapper = vissweep.vtkVisibilitySweepVolumeMapper()
mapper.SetInputConnection(reader.GetOutputPort())
mapper.SetEnvironmentConnection(env.GetOutputPort())
volume = vtk.vtkVolume()
volume.SetMapper(mapper)
volume.SetProperty(prop)
ren = vtk.vtkRenderer()
ren.AddVolume(volume)
win = vtk.vtkRenderWindow()
win.SetOffScreenRendering(1)
win.SetSize(args.size, args.size)
win.AddRenderer(ren)
camera = ren.GetActiveCamera()
camera.SetPosition(0, 1, 0)
camera.SetViewUp(0, 0, 1)
ren.ResetCamera()
key = vtk.vtkLight()
key.SetLightTypeToSceneLight()
key.SetPositional(False)
key.SetPosition(200, 150, 200)
key.SetFocalPoint(0, 0, 0)
key.SetIntensity(3.0)
key.SetColor(1.0, 0.95, 0.9)
ren.AddLight(key)
configs = ["no light", "key light", "key + ShadeOn", "ShadeOn"]


def setup(c):
    key.SetSwitch(c.startswith("key"))
    prop.SetShade(c.endswith("ShadeOn"))


frames = {c: [] for c in configs}
first = {c: [] for c in configs}
win.SetDesiredUpdateRate(15.0)
for c in configs:  # warm: pipelines
    setup(c)
    win.Render()
for rnd in range(args.rounds):
    for c in configs:
        setup(c)
        camera.Azimuth(2.0)
        t = time.perf_counter()
        win.Render()  # builds the light volume again where the lights changed
        first[c].append(time.perf_counter() - t)
        for k in range(3):
            camera.Azimuth(2.0)
            t = time.perf_counter()
            win.Render()
            frames[c].append(time.perf_counter() - t)
for c in configs:
    print("%-14s drag frame median %6.1f ms (min %6.1f, max %6.1f, %d frames); a round's first frame median %6.1f ms"
          % (c, 1e3 * statistics.median(frames[c]), 1e3 * min(frames[c]), 1e3 * max(frames[c]), len(frames[c]),
             1e3 * statistics.median(first[c])))
print("light volume builds", mapper.GetLightVolumeBuildCount(), "error:", mapper.GetLastError() or "none")
