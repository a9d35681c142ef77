"""VisSweep in ParaView's Python: pvpython, pvbatch and the GUI's Python shell.

    from paraview.simple import *
    import vissweep.paraview as vsp
    vsp.load_plugin(ns=globals())        # the plugin here, and on the server when connected to one
    display = Show(OpenDataFile("Examples/Scenes/tiny_sphere.vti"), view)
    display.Representation = "VisSweep Volume"
    samples, seconds = vsp.refine(display, view, time_budget=5.0)

This module needs the package built against ParaView's VTK 9.2 (build-pv/vissweep, made by
scripts/paraview-check.sh and scripts/paraview-plugin.sh): the package in build/ is linked to
Debian's VTK 9.1, and two VTKs in one process crash (docs/paraview.md). The package's classes
(`vissweep.vtkVisibilitySweepVolumeMapper` and the others) then work in a VTK pipeline in pvpython
too; ParaView's own pipeline reaches the mapper through the plugin's "VisSweep Volume"
representation and its properties, which is what these helpers set.
"""
import glob
import os
import time

PLUGIN_FILE = "VisSweep.so"


def plugin_path():
    """The plugin's file: $VISSWEEP_PARAVIEW_PLUGIN; else VisSweep/VisSweep.so (or VisSweep.so) in a
    folder of $PV_PLUGIN_PATH; else the build beside this package (the repository's
    build-pv-plugin/lib/paraview-5.11/plugins/VisSweep/VisSweep.so, with the package in build-pv/).
    Raises FileNotFoundError naming where it looked."""
    looked = []
    given = os.environ.get("VISSWEEP_PARAVIEW_PLUGIN")
    if given:
        if os.path.isfile(given):
            return given
        raise FileNotFoundError(f"VISSWEEP_PARAVIEW_PLUGIN names {given}, which is not a file")
    for folder in filter(None, os.environ.get("PV_PLUGIN_PATH", "").split(os.pathsep)):
        for candidate in (os.path.join(folder, "VisSweep", PLUGIN_FILE), os.path.join(folder, PLUGIN_FILE)):
            looked.append(candidate)
            if os.path.isfile(candidate):
                return candidate
    # This file is <build-pv>/<site>/vissweep/paraview.py (<site>: lib/python3.X/dist-packages).
    here = os.path.dirname(os.path.realpath(__file__))
    build = here
    for _ in range(4):
        build = os.path.dirname(build)
    pattern = os.path.join(os.path.dirname(build), "build-pv-plugin", "lib", "paraview-*", "plugins",
                           "VisSweep", PLUGIN_FILE)
    looked.append(pattern)
    found = sorted(glob.glob(pattern))
    if found:
        return found[-1]
    raise FileNotFoundError("the VisSweep ParaView plugin was not found (set VISSWEEP_PARAVIEW_PLUGIN or "
                            "PV_PLUGIN_PATH, or build it with scripts/paraview-plugin.sh); looked at: "
                            + ", ".join(looked))


def load_plugin(path=None, ns=None):
    """Loads the plugin (path: plugin_path()'s by default) in this process and, when connected to a
    pvserver, on the server too. ns: the namespace that gets the plugin's readers, as for
    paraview.simple.LoadPlugin (globals() in a script). Returns the path."""
    from paraview import servermanager, simple

    path = path or plugin_path()
    connection = servermanager.ActiveConnection
    if connection is not None and connection.IsRemote():
        simple.LoadPlugin(path, remote=True, ns=ns)
    simple.LoadPlugin(path, remote=False, ns=ns)
    return path


def set_environment(display, file_name=None, intensity=None, rotation=None, visible=None):
    """Sets a VisSweep Volume display's environment: a lat-long .exr/.hdr file ("" or None: the white
    sky), its intensity, its rotation about +Z in degrees and whether it is seen behind the volume.
    A file that does not exist here is refused (FileNotFoundError) in a builtin session; with a
    pvserver the file is the server's, and a wrong name is the server's error."""
    from paraview import servermanager

    if file_name:
        connection = servermanager.ActiveConnection
        remote = connection is not None and connection.IsRemote()
        if not remote and not os.path.isfile(file_name):
            raise FileNotFoundError(f"environment file {file_name} does not exist")
    display.EnvironmentFileName = file_name or ""
    if intensity is not None:
        display.EnvironmentIntensity = intensity
    if rotation is not None:
        display.EnvironmentRotation = rotation
    if visible is not None:
        display.EnvironmentVisible = int(bool(visible))


def refine(display, view=None, time_budget=None, maximum_samples=None, samples_per_frame=None,
           timeout=None):
    """Renders a still view until its VisSweep Volume display is converged: MaximumSamples reached or
    its TimeBudget spent (time_budget, maximum_samples and samples_per_frame set those properties
    first; None keeps them). Returns (samples per pixel, seconds of rendering the accumulation took,
    as the representation's AccumulationTime counts them). Raises RuntimeError with the mapper's
    error when a render fails, and TimeoutError after `timeout` wall seconds."""
    from paraview import simple

    view = view or simple.GetActiveView()
    if display.GetProperty("Converged") is None:
        raise ValueError("not a display with VisSweep's properties (load the plugin first)")
    if display.Representation != "VisSweep Volume":
        display.Representation = "VisSweep Volume"
    if samples_per_frame is not None:
        display.SamplesPerFrame = samples_per_frame
    if maximum_samples is not None:
        display.MaximumSamples = maximum_samples
    if time_budget is not None:
        display.TimeBudget = time_budget
    start = time.monotonic()
    while True:
        simple.Render(view)
        display.UpdatePropertyInformation()
        error = display.GetPropertyValue("LastError")
        if error:
            raise RuntimeError(f"VisSweep: {error}")
        if display.GetPropertyValue("Converged"):
            return display.GetPropertyValue("AccumulatedSamples"), display.GetPropertyValue("AccumulationTime")
        if timeout is not None and time.monotonic() - start > timeout:
            raise TimeoutError(f"not converged after {timeout} s ("
                               f"{display.GetPropertyValue('AccumulatedSamples')} samples per pixel)")
