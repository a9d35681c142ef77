#!/usr/bin/env python3
"""Issue 38 item 4: the preview's drag frames with VTK's lights and the surface lobe. Full ch2 under the
sunrise HDRI at 512^2 (the README's transfer function), the Monte Carlo mode's preview while dragging
(desired update rate 15, a 2-degree azimuth per frame): no light, a directional key light (intensity 3),
the key light with ShadeOn, ShadeOn alone. The configurations take turns (6 rounds of 1 + 3 frames each),
so that a loaded machine slows them alike; a round's first frame builds the light volume again when the
lights changed (reported apart). Prints the median wall time of Render() per configuration.

    PYTHONPATH=build LP_NUM_THREADS=2 xvfb-run -a /usr/bin/python3 Benchmarks/preview_lights_frames.py
"""
import os
import statistics
import time

import vtk
import vissweep

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
reader = vtk.vtkNIFTIImageReader()
reader.SetFileName("/usr/share/mricron/templates/ch2.nii.gz")
env = vissweep.vtkEnvironmentMapReader()
env.SetFileName(os.path.join(root, "Data", "envmaps", "sunrise.exr"))
prop = vtk.vtkVolumeProperty()
opacity = vtk.vtkPiecewiseFunction()
for s, a in ((0, 0.0), (40, 0.0), (90, 0.05), (255, 0.3)):
    opacity.AddPoint(s, a)
color = vtk.vtkColorTransferFunction()
color.AddRGBPoint(0, 0, 0, 0)
color.AddRGBPoint(90, 0.9, 0.6, 0.5)
color.AddRGBPoint(255, 1.0, 1.0, 0.9)
prop.SetScalarOpacity(opacity)
prop.SetColor(color)
prop.SetInterpolationTypeToLinear()
prop.SetScalarOpacityUnitDistance(1.0)
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
win.SetSize(512, 512)
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
for rnd in range(6):
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
