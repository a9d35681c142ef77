"""What the plugin's pvbatch and pvpython tests share (pvbatch_vissweep.py, pvbatch_mpi.py,
pvpython_client.py): checks that record their failures, a PNG as an array, the tiny sphere shown
with the "VisSweep Volume" representation, an image's agreement with a reference render within the
reference's noise, and the verdict file the drivers read.

The scripts import it from their own folder (pvbatch and pvpython put the script's folder on
sys.path as python does; the scripts add it themselves in case a launcher does not).
"""
import numpy as np
import paraview.simple as pvs
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

failures = []


def check(ok, what):
    """Prints the check's verdict and records a failure."""
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def png(path):
    """The PNG's RGB as float64, rows from the bottom (VTK's order), shape (height, width, 3)."""
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).astype(np.float64)
    return a.reshape(h, w, -1)[:, :, :3]


def show_tiny_sphere(volume, size=64):
    """Shows VOLUME (Examples/Scenes/tiny_sphere.vti) in a new render view of size x size with the
    "VisSweep Volume" representation and Examples/Scenes/tiny.json's transfer functions, unit distance
    and camera, Monte Carlo with TwoStep sampling and seed 1. Returns (reader, view, display)."""
    reader = pvs.XMLImageDataReader(FileName=[volume])
    view = pvs.CreateView("RenderView")
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    display = pvs.Show(reader, view)
    representations = display.GetProperty("Representation")
    check("VisSweep Volume" in representations.Available if hasattr(representations, "Available") else True,
          "the plugin adds the 'VisSweep Volume' representation")
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
    view.CameraPosition = [7.5, -40, 12]
    view.CameraFocalPoint = [7.5, 7.5, 7.5]
    view.CameraViewUp = [0, 0, 1]
    view.CameraViewAngle = 30
    return reader, view, display


def agrees(image, reference, second, what, reference_name):
    """Checks that IMAGE is REFERENCE's render within its noise, measured by SECOND (the reference's
    render with another seed): the means within 4 standard errors of one image's mean, and the mean
    |pixel difference| at most 1.5 times the two reference renders' (plus 1 for 8-bit rounding).
    WHAT names the image, REFERENCE_NAME the reference. Returns the standard error."""
    noise = (reference - second).mean(axis=2)
    stderr = noise.std() / np.sqrt(noise.size)  # standard error of one image's mean
    diff = image.mean() - reference.mean()
    print("means: %s %.3f, %s %.3f (another seed %.3f); standard error %.3f"
          % (what, image.mean(), reference_name, reference.mean(), second.mean(), stderr), flush=True)
    check(abs(diff) <= 4 * stderr + 0.5,
          "%s: its mean is within 4 standard errors of %s (%.3f)" % (what, reference_name, diff))
    pix, pix_noise = np.abs(image - reference).mean(), np.abs(reference - second).mean()
    print("mean |pixel difference|: %s - %s %.3f, two seeds %.3f" % (what, reference_name, pix, pix_noise),
          flush=True)
    check(pix <= 1.5 * pix_noise + 1.0, "%s: its pixels agree with %s as two seeds' do" % (what, reference_name))
    return stderr


def finish(path):
    """Prints and writes the verdict. It goes to a file, not the exit status: sys.exit() in a pvbatch
    script ends pvbatch with "X Error of failed request: GLXBadContext" and status 1 as it tears the
    window down (seen with ParaView's own Volume representation too, without the plugin), so the
    drivers read the file."""
    print("%d failure(s)" % len(failures))
    with open(path, "w") as f:
        f.write("%d failure(s)\n" % len(failures))
