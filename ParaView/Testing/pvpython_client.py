"""A pvpython client of `mpiexec -n 2 pvserver` (run by run-mpi-test.sh, which says how).

  pvpython pvpython_client.py PLUGIN VOLUME OUTDIR PORT

Connects to the pvserver on localhost:PORT, loads the plugin on both sides and renders the tiny
sphere as pvbatch_mpi.py does (SamplesPerFrame 8, MaximumSamples 16): the client must read the
server's samples (16 and converged after one frame of 8 per process; a client reads its own copy
of the representation, which never renders, unless the plugin's proxy asks the server), and the
image made on the server must be the single process's within its noise. Writes "N failure(s)"
to OUTDIR/result-client.txt.
"""
import sys

import paraview.simple as pvs
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
import numpy as np

plugin, volume, outdir, port = sys.argv[1:5]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def png(path):
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).astype(np.float64)
    return a.reshape(h, w, -1)[:, :, :3]


pvs.Connect("localhost", int(port))
pvs.LoadPlugin(plugin, remote=True, ns=globals())
pvs.LoadPlugin(plugin, remote=False, ns=globals())
pvs._DisableFirstRenderCameraReset()

reader = pvs.XMLImageDataReader(FileName=[volume])
view = pvs.CreateView("RenderView")
view.ViewSize = [64, 64]
view.OrientationAxesVisibility = 0
view.RemoteRenderThreshold = 0  # the image is made on the server
display = pvs.Show(reader, view)
display.Representation = "VisSweep Volume"
pvs.ColorBy(display, ("POINTS", "density"))
lut = pvs.GetColorTransferFunction("density")
lut.AutomaticRescaleRangeMode = "Never"
lut.ColorSpace = "RGB"
lut.Discretize = 0
lut.RGBPoints = [0, 0.9, 0.9, 0.9, 255, 0.8, 0.5, 0.3]
otf = pvs.GetOpacityTransferFunction("density")
otf.Points = [0, 0.0, 0.5, 0.0, 20, 0.0, 0.5, 0.0, 120, 0.5, 0.5, 0.0, 255, 0.9, 0.5, 0.0]
display.ScalarOpacityUnitDistance = 1.0
display.VisSweepRenderMode = "Monte Carlo"
display.SamplingStrategy = "Two-Step"
display.Seed = 1
display.EnvironmentVisible = 0
display.SamplesPerFrame = 8
display.MaximumSamples = 16
view.CameraPosition = [7.5, -40, 12]
view.CameraFocalPoint = [7.5, 7.5, 7.5]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 30
view.DepthPeelingForVolumes = 0

pvs.Render(view)
pvs.SaveScreenshot(outdir + "/client.png", view, ImageResolution=[64, 64])
display.UpdatePropertyInformation()
counts = (display.GetPropertyValue("AccumulatedSamples"), display.GetPropertyValue("Converged"))
print("the client reads: accumulated, converged =", counts, flush=True)
check(counts == (16, 1), "the client reads the server's 16 samples per pixel (2 x 8), converged")
a, b1, b2 = png(outdir + "/client.png"), png(outdir + "/single-seed1.png"), png(outdir + "/single-seed2.png")
noise = (b1 - b2).mean(axis=2)
stderr = noise.std() / np.sqrt(noise.size)
print("means: client of 2 pvservers %.3f, 1 pvbatch process %.3f; standard error %.3f"
      % (a.mean(), b1.mean(), stderr), flush=True)
check(abs(a.mean() - b1.mean()) <= 4 * stderr + 0.5,
      "the image made by 2 pvserver processes is the single process's within 4 standard errors")
check(np.abs(a - b1).mean() <= 1.5 * np.abs(b1 - b2).mean() + 1.0,
      "its pixels agree with the single process's as two seeds' do")

print("%d failure(s)" % len(failures))
with open(outdir + "/result-client.txt", "w") as f:
    f.write("%d failure(s)\n" % len(failures))
pvs.Disconnect()
