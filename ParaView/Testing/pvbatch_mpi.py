"""The VisSweep plugin under MPI (run by run-mpi-test.sh, which says how).

  pvbatch pvbatch_mpi.py PLUGIN VOLUME OUTDIR single
  mpiexec -n 2 pvbatch --mpi pvbatch_mpi.py PLUGIN VOLUME OUTDIR mpi

Shows VOLUME (Examples/Scenes/tiny.json's sphere, its transfer functions and camera) with the
"VisSweep Volume" representation under the white sky at 64 x 64.

single: one process renders 16 samples per pixel with seeds 1 and 2 (EnvironmentVisible off, as
  it is taken under MPI) into OUTDIR/single-seed1.png and single-seed2.png, then times frames.
mpi: two processes (each given half of the volume by ParaView) render with SamplesPerFrame 8 and
  MaximumSamples 16: one frame must bring all 16 samples per pixel (8 per process, averaged), and
  the image must be the single process's within its noise (the mean within 4 standard errors
  estimated from the two seeds, the pixels as close as the two seeds' are); a TimeBudget stops
  both processes at the same frame. Then times frames.
Writes "N failure(s)" to OUTDIR/result-MODE.txt and the frame times to OUTDIR/timing-MODE.txt.
"""
import os
import sys
import time

import paraview.simple as pvs
from paraview.modules.vtkRemotingCore import vtkProcessModule

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from vissweep_pvtest import agrees, check, finish, png, show_tiny_sphere  # noqa: E402

plugin, volume, outdir, mode = sys.argv[1:5]

pvs.LoadPlugin(plugin, remote=False, ns=globals())
pvs._DisableFirstRenderCameraReset()
processes = vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
print("%s: %d process(es)" % (mode, processes), flush=True)

reader, view, display = show_tiny_sphere(volume)
view.DepthPeelingForVolumes = 0


def samples():
    display.UpdatePropertyInformation()
    return display.GetPropertyValue("AccumulatedSamples"), display.GetPropertyValue("Converged")


def timing(frames=3):
    """Seconds per frame of SamplesPerFrame 16 at 128 x 128 (after one frame of warm-up)."""
    view.ViewSize = [128, 128]
    display.SamplesPerFrame = 16
    display.MaximumSamples = 1 << 20
    pvs.Render(view)
    start = time.perf_counter()
    for _ in range(frames):
        pvs.Render(view)
    seconds = (time.perf_counter() - start) / frames
    count = samples()[0]
    with open("%s/timing-%s.txt" % (outdir, mode), "w") as f:
        f.write("%d %.4f %d\n" % (processes, seconds, count))
    print("%s: %.3f s per frame of 16 spp per process at 128 x 128 (%d processes, %d spp after %d frames)"
          % (mode, seconds, processes, count, frames + 1), flush=True)


if mode == "single":
    check(processes == 1, "one process")
    display.EnvironmentVisible = 0
    display.SamplesPerFrame = 16
    display.MaximumSamples = 16
    for seed in (1, 2):
        display.Seed = seed
        pvs.Render(view)
        pvs.SaveScreenshot("%s/single-seed%d.png" % (outdir, seed), view, ImageResolution=[64, 64])
        check(samples() == (16, 1), "seed %d: 16 samples per pixel in one frame, converged" % seed)
    display.Seed = 1
    timing()
else:
    check(processes == 2, "two processes (mpiexec -n 2 pvbatch --mpi)")
    # EnvironmentVisible stays on (the default): under MPI it is taken as off, with a warning
    # (the driver checks stderr), and the image must be the single process's with it off.
    display.SamplesPerFrame = 8
    display.MaximumSamples = 16
    pvs.Render(view)
    pvs.SaveScreenshot(outdir + "/mpi.png", view, ImageResolution=[64, 64])
    counts = samples()
    print("after one frame of 8 samples per process: accumulated, converged =", counts, flush=True)
    check(counts == (16, 1), "one frame of 8 samples per pixel per process gives 16, converged")
    a, b1, b2 = png(outdir + "/mpi.png"), png(outdir + "/single-seed1.png"), png(outdir + "/single-seed2.png")
    agrees(a, b1, b2, "the 2-process image", "the 1-process image")
    check(a.std() > 5, "the image is not flat (the volume is drawn)")
    pvs.Render(view)
    check(samples() == (16, 1), "a further render adds nothing (converged)")
    # A time budget under MPI: the processes decide from the same (reduced) frame times, so both
    # stop at the same frame: every render adds 2 x 1 samples per pixel until the budget, then none.
    display.SamplesPerFrame = 1
    display.MaximumSamples = 1 << 20
    display.TimeBudget = 1.0
    display.Seed = 3
    counts = []
    start = time.time()
    while time.time() - start < 60:
        pvs.Render(view)
        counts.append(samples())
        if counts[-1][1]:
            break
    reached = counts[-1][0]
    print("time budget 1 s with 2 processes: %d spp in %d renders (%s ... %s)"
          % (reached, len(counts), counts[:2], counts[-2:]), flush=True)
    check(counts[-1][1] == 1 and [c[0] for c in counts] == list(range(2, reached + 1, 2)) + [reached],
          "both processes stop at the budget's frame (2 samples per render, then none, converged)")
    display.TimeBudget = 0
    display.Seed = 1
    timing()

finish("%s/result-%s.txt" % (outdir, mode))
