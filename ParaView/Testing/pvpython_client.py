"""A pvpython client of `mpiexec -n 2 pvserver` (run by run-mpi-test.sh, which says how).

  pvpython pvpython_client.py PLUGIN VOLUME OUTDIR PORT

Connects to the pvserver on localhost:PORT, loads the plugin on both sides and renders the tiny
sphere as pvbatch_mpi.py does (SamplesPerFrame 8, MaximumSamples 16): the client must read the
server's samples (16 and converged after one frame of 8 per process; a client reads its own copy
of the representation, which never renders, unless the plugin's proxy asks the server), and the
image made on the server must be the single process's within its noise. Writes "N failure(s)"
to OUTDIR/result-client.txt.
"""
import os
import sys

import paraview.simple as pvs

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from vissweep_pvtest import agrees, check, finish, png, show_tiny_sphere  # noqa: E402

plugin, volume, outdir, port = sys.argv[1:5]

pvs.Connect("localhost", int(port))
pvs.LoadPlugin(plugin, remote=True, ns=globals())
pvs.LoadPlugin(plugin, remote=False, ns=globals())
pvs._DisableFirstRenderCameraReset()

reader, view, display = show_tiny_sphere(volume)
view.RemoteRenderThreshold = 0  # the image is made on the server
view.DepthPeelingForVolumes = 0
display.EnvironmentVisible = 0
display.SamplesPerFrame = 8
display.MaximumSamples = 16

pvs.Render(view)
pvs.SaveScreenshot(outdir + "/client.png", view, ImageResolution=[64, 64])
display.UpdatePropertyInformation()
counts = (display.GetPropertyValue("AccumulatedSamples"), display.GetPropertyValue("Converged"))
print("the client reads: accumulated, converged =", counts, flush=True)
check(counts == (16, 1), "the client reads the server's 16 samples per pixel (2 x 8), converged")
a, b1, b2 = png(outdir + "/client.png"), png(outdir + "/single-seed1.png"), png(outdir + "/single-seed2.png")
agrees(a, b1, b2, "the image of 2 pvserver processes", "the single pvbatch process's image")
finish(outdir + "/result-client.txt")
pvs.Disconnect()
