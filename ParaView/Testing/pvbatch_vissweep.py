"""pvbatch test of the VisSweep plugin (run by run-pvbatch-test.sh, which says how).

  pvbatch pvbatch_vissweep.py PLUGIN VOLUME OUTDIR TOOL_SEED1_PNG TOOL_SEED2_PNG

Loads the plugin, shows VOLUME (the tool's tiny scene: Examples/Scenes/tiny.json without its sun,
i.e. the white sky) with the "VisSweep Volume" representation, renders it at 64 x 64 with 16
samples per pixel and compares the image with the vissweep tool's renders of the same scene
(seeds 1 and 2): the means must agree within 4 standard errors (estimated from the two tool
renders' difference), and the pixels as closely as two tool renders agree. Then checks that
properties reach the mapper (Exposure brightens the image, single scattering darkens it), that a missing environment file
is an error, not a crash, after which the volume renders again, that renders refine
progressively and stop at a TimeBudget, and that a state file keeps the settings. Writes "N failure(s)" to OUTDIR/result.txt.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
import paraview.simple as pvs

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))
from vissweep_pvtest import agrees, check, finish, png, show_tiny_sphere  # noqa: E402

plugin, volume, outdir, tool1, tool2 = sys.argv[1:6]

pvs.LoadPlugin(plugin, remote=False, ns=globals())
pvs._DisableFirstRenderCameraReset()

reader, view, display = show_tiny_sphere(volume)
# ParaView's Light Kit (on by default) lights a VisSweep volume beside the environment (VTK's lights,
# issue 38), as it does OSPRay's path tracer; the tool's scene has the environment alone.
view.UseLight = 0
display.SamplesPerFrame = 16
display.MaximumSamples = 16

pvs.Render(view)
pvs.SaveScreenshot(outdir + "/pv.png", view, ImageResolution=[64, 64])
a, b1, b2 = png(outdir + "/pv.png"), png(tool1), png(tool2)
stderr = agrees(a, b1, b2, "ParaView's image", "the tool's image")
check(a.std() > 5, "the image is not flat (the volume is drawn)")

# A property change reaches the mapper and re-renders.
display.Exposure = 4.0
pvs.Render(view)
pvs.SaveScreenshot(outdir + "/pv-exposure4.png", view, ImageResolution=[64, 64])
bright = png(outdir + "/pv-exposure4.png")
check(bright.mean() > a.mean() + 5, "Exposure 4 brightens the image (%.1f -> %.1f)"
      % (a.mean(), bright.mean()))
display.Exposure = 1.0

# The scattering settings reach the mapper: single scattering (one event) loses the light of the
# longer paths, so the sphere darkens; an anisotropy outside (-1, 1) is a warning naming it (the
# driver checks stderr) and the mapper's error, then the volume renders again.
display.MaximumScatteringEvents = 1
pvs.Render(view)
pvs.SaveScreenshot(outdir + "/pv-single-scattering.png", view, ImageResolution=[64, 64])
single = png(outdir + "/pv-single-scattering.png")
check(single.mean() < a.mean() - 2, "MaximumScatteringEvents 1 darkens the image (%.1f -> %.1f)"
      % (a.mean(), single.mean()))
display.MaximumScatteringEvents = 1024
display.ScatteringAnisotropy = 1.5
pvs.Render(view)
print("rendered with ScatteringAnisotropy 1.5", flush=True)
display.ScatteringAnisotropy = 0.0

# Bad input: a missing environment file is reported (the driver checks the message), no crash.
display.EnvironmentFileName = outdir + "/missing-sky.exr"
pvs.Render(view)
pvs.SaveScreenshot(outdir + "/pv-missing-env.png", view, ImageResolution=[64, 64])
print("rendered with a missing environment file", flush=True)
display.EnvironmentFileName = ""
pvs.Render(view)
pvs.SaveScreenshot(outdir + "/pv-again.png", view, ImageResolution=[64, 64])
again = png(outdir + "/pv-again.png")
check(abs(again.mean() - a.mean()) <= 4 * stderr + 0.5,
      "with the file name cleared the volume renders as before (%.3f vs %.3f)"
      % (again.mean(), a.mean()))

# Out-of-range settings from a script (the panel's domains stop them in the GUI) are warned about
# with the setting's name and the value used (the driver checks the messages); NaN is refused.
display.SamplesPerFrame = 0
display.Exposure = float("nan")
pvs.Render(view)
print("rendered with out-of-range settings", flush=True)
display.SamplesPerFrame = 16
display.Exposure = 1.0

# Progressive refinement: each still render adds SamplesPerFrame until MaximumSamples, which
# the Converged and AccumulatedSamples information properties report to the client. The view
# holds 16 samples per pixel (converged at MaximumSamples 16): raised to 28, renders continue.
display.SamplesPerFrame = 4
display.MaximumSamples = 28
counts = []
for _ in range(5):
    pvs.Render(view)
    display.UpdatePropertyInformation()
    counts.append((display.GetPropertyValue("AccumulatedSamples"),
                   display.GetPropertyValue("Converged")))
print("accumulated samples, converged after each render:", counts)
check([c[0] for c in counts] == [20, 24, 28, 28, 28] and [c[1] for c in counts] == [0, 0, 1, 1, 1],
      "renders refine 4 samples at a time until MaximumSamples (28), then report convergence")

# The time budget: with SamplesPerFrame 1 and MaximumSamples far away, a still view refines until
# TimeBudget seconds of rendering (its frames' times summed) are spent, then stops: Converged 1, and
# further renders add nothing. Every frame within the budget added its sample, the one after none.
import time
budget = 1.0
display.SamplesPerFrame = 1
display.MaximumSamples = 1 << 20
display.TimeBudget = budget
display.Seed = 5  # restarts the accumulation (and the budget's clock)
budget_counts = []
converged = 0
start = time.time()
while time.time() - start < 20 * budget + 30:
    pvs.Render(view)
    display.UpdatePropertyInformation()
    budget_counts.append(display.GetPropertyValue("AccumulatedSamples"))
    converged = display.GetPropertyValue("Converged")
    if converged:
        break
wall = time.time() - start
spent = display.GetPropertyValue("AccumulationTime")
reached = budget_counts[-1] if budget_counts else 0
print("time budget %.1f s: %d spp in %d renders, AccumulationTime %.3f s, loop %.3f s, converged %d"
      % (budget, reached, len(budget_counts), spent, wall, converged), flush=True)
check(converged == 1 and 1 < reached < 1 << 20,
      "a still view stops refining when its TimeBudget is spent (%d spp of 1048576)" % reached)
check(budget_counts == list(range(1, reached + 1)) + [reached],
      "each render within the budget added SamplesPerFrame (1), the one after it none (%s)"
      % (budget_counts[:3] + ["..."] + budget_counts[-3:]))
check(0.5 * budget <= spent <= budget,
      "the accumulation's render time (%.3f s) is within the budget (%.1f s) and uses most of it" % (spent, budget))
pvs.Render(view)
pvs.Render(view)
display.UpdatePropertyInformation()
check(display.GetPropertyValue("AccumulatedSamples") == reached and display.GetPropertyValue("Converged") == 1,
      "renders after the budget is spent add nothing")
display.TimeBudget = 0  # no budget: refinement resumes
pvs.Render(view)
display.UpdatePropertyInformation()
check(display.GetPropertyValue("AccumulatedSamples") == reached + 1 and display.GetPropertyValue("Converged") == 0,
      "without the budget the same accumulation resumes (%d -> %d spp)"
      % (reached, display.GetPropertyValue("AccumulatedSamples")))
display.TimeBudget = -1.0  # a warning naming it (the driver checks stderr); 0 is used
display.TimeBudget = 0
display.SamplesPerFrame = 4
display.MaximumSamples = 28
display.Seed = 1

# A state file keeps the representation and its settings.
display.TimeBudget = 2.5
display.Exposure = 2.5
display.VisSweepRenderMode = "Preview"
display.EnvironmentRotation = 30
display.MaximumScatteringEvents = 8
display.ScatteringAnisotropy = 0.25
display.MultipleImportanceSampling = "Balance Heuristic"
pvs.SaveState(outdir + "/state.pvsm")
pvs.ResetSession()
pvs.LoadState(outdir + "/state.pvsm")
loaded_view = pvs.GetActiveViewOrCreate("RenderView")
loaded = pvs.GetDisplayProperties(pvs.FindSource("XMLImageDataReader1"), loaded_view)
values = (loaded.Representation, loaded.Exposure, loaded.VisSweepRenderMode,
          loaded.EnvironmentRotation, loaded.SamplesPerFrame, loaded.MaximumSamples,
          loaded.MaximumScatteringEvents, loaded.ScatteringAnisotropy, loaded.MultipleImportanceSampling,
          loaded.TimeBudget)
print("after LoadState:", values)
check(values == ("VisSweep Volume", 2.5, "Preview", 30.0, 4, 28, 8, 0.25, "Balance Heuristic", 2.5),
      "a saved state (.pvsm) loads back with the VisSweep representation and its settings")

# VisSweep's OpenVDB reader: File > Open (OpenDataFile) reads a .vdb file with it, the smoke renders
# with VisSweep, and a grid the file does not have is an error naming it (the driver checks stderr).
smoke_file = os.path.join(os.path.dirname(volume), "..", "..", "Data", "smoke", "smoke_0004.vdb")
smoke = pvs.OpenDataFile(smoke_file)
check(smoke is not None and smoke.GetXMLName() == "VisSweepOpenVDBReader",
      "OpenDataFile reads a .vdb file with VisSweep's reader (%s)" % (smoke and smoke.GetXMLName()))
if smoke is not None:
    smoke.UpdatePipeline()
    points = smoke.GetDataInformation().GetNumberOfPoints()
    arrays = [smoke.PointData[i].GetName() for i in range(len(smoke.PointData))]
    print("the smoke: %d points, arrays %s" % (points, arrays))
    check(points > 1000 and "density" in arrays, "the smoke's density grid is read")
    smoke_view = pvs.CreateView("RenderView")
    smoke_view.ViewSize = [32, 32]
    smoke_view.OrientationAxesVisibility = 0
    smoke_display = pvs.Show(smoke, smoke_view)
    smoke_display.Representation = "VisSweep Volume"
    pvs.ColorBy(smoke_display, ("POINTS", "density"))
    smoke_display.SamplesPerFrame = 4
    smoke_display.MaximumSamples = 4
    smoke_display.EnvironmentVisible = 0
    smoke_view.ResetCamera()
    pvs.Render(smoke_view)
    pvs.SaveScreenshot(outdir + "/smoke.png", smoke_view, ImageResolution=[32, 32])
    smoke_image = png(outdir + "/smoke.png")
    check(smoke_image.std() > 2, "the smoke renders (pixel deviation %.1f)" % smoke_image.std())
    smoke.GridName = "no-such-grid"
    smoke.UpdatePipeline()
    print("read a grid the file does not have", flush=True)

# The vissweep Python package built against ParaView's VTK (build-pv/vissweep, on PYTHONPATH): its
# wrapped classes in a VTK pipeline inside pvbatch, and its ParaView helpers (vissweep.paraview).
try:
    import vissweep
    import vissweep.paraview as vsp
except ImportError as e:
    vissweep = None
    check(False, "import vissweep and vissweep.paraview in pvbatch (%s)" % e)
if vissweep is not None:
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderWindow, vtkRenderer,
                                             vtkVolume, vtkVolumeProperty)
    mapper = vissweep.vtkVisibilitySweepVolumeMapper()
    check(mapper.GetClassName() == "vtkVisibilitySweepVolumeMapper" and mapper.MonteCarlo == 1,
          "import vissweep in pvbatch gives the wrapped mapper and its constants (%s)" % vissweep.__file__)
    vti = vtkXMLImageDataReader()
    vti.SetFileName(volume)
    mapper.SetInputConnection(vti.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray("density")
    mapper.SetSamplesPerFrame(4)
    mapper.SetMaximumSamples(4)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0, 0.0)
    opacity.AddPoint(255, 0.9)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0, 0.9, 0.9, 0.9)
    vprop = vtkVolumeProperty()
    vprop.SetScalarOpacity(opacity)
    vprop.SetColor(colour)
    vtk_volume = vtkVolume()
    vtk_volume.SetMapper(mapper)
    vtk_volume.SetProperty(vprop)
    renderer = vtkRenderer()
    renderer.AddVolume(vtk_volume)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(32, 32)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    window.Render()
    check(mapper.GetAccumulatedSamples() == 4 and not mapper.GetLastError(),
          "the wrapped mapper renders in a VTK pipeline in pvbatch (%d spp, error '%s')"
          % (mapper.GetAccumulatedSamples(), mapper.GetLastError() or ""))
    window.Finalize()
    check(os.path.samefile(vsp.plugin_path(), plugin),
          "vissweep.paraview.plugin_path() finds the plugin beside the package (%s)" % vsp.plugin_path())
    try:
        vsp.set_environment(loaded, os.path.join(outdir, "no-such-sky.exr"))
        check(False, "vissweep.paraview.set_environment refuses a missing file")
    except FileNotFoundError as e:
        check("no-such-sky.exr" in str(e), "vissweep.paraview.set_environment refuses a missing file (%s)" % e)
    loaded.VisSweepRenderMode = "Monte Carlo"
    refined = vsp.refine(loaded, loaded_view, time_budget=0, maximum_samples=8, samples_per_frame=4, timeout=120)
    print("vissweep.paraview.refine:", refined, flush=True)
    check(refined[0] == 8 and refined[1] > 0,
          "vissweep.paraview.refine renders a still view until it is converged (%d spp, %.3f s)" % refined)

finish(outdir + "/result.txt")
