"""The README's GUI screenshot (docs/paraview_gui.png): tiny.json's volume, transfer functions and
camera under the white sky, refined by the plugin's timer to 256 samples per pixel. Made with
  XDG_CONFIG_HOME=<a folder whose ParaView/ParaView5.11.0.ini has GeneralSettings.ShowWelcomeDialog=false>
  VS_PLUGIN=<VisSweep.so> VS_VOLUME=Examples/Scenes/tiny_sphere.vti xvfb-run -s "-screen 0 1280x800x24"
  unshare -m scripts/paraview-check.sh --inside paraview --verbosity=INFO --script=ParaView/Testing/gui_screenshot.py
and, once it logs "converged at 256", ImageMagick's `import -window root`, cropped to the window."""
from paraview.simple import *
import os
LoadPlugin(os.environ["VS_PLUGIN"], remote=False, ns=globals())
r = XMLImageDataReader(registrationName="tiny_sphere.vti", FileName=[os.environ["VS_VOLUME"]])
v = GetActiveViewOrCreate("RenderView")
v.OrientationAxesVisibility = 0
v.DepthPeelingForVolumes = 0
d = Show(r, v); d.Representation = "VisSweep Volume"; ColorBy(d, ("POINTS", "density"))
lut = GetColorTransferFunction("density"); lut.AutomaticRescaleRangeMode = "Never"; lut.ColorSpace = "RGB"; lut.Discretize = 0
lut.RGBPoints = [0, 0.9, 0.9, 0.9, 255, 0.8, 0.5, 0.3]
otf = GetOpacityTransferFunction("density")
otf.Points = [0, 0.0, 0.5, 0.0, 20, 0.0, 0.5, 0.0, 120, 0.5, 0.5, 0.0, 255, 0.9, 0.5, 0.0]
d.ScalarOpacityUnitDistance = 1.0
d.SamplesPerFrame = 8; d.MaximumSamples = 256
v.CameraPosition = [7.5, -40, 12]; v.CameraFocalPoint = [7.5, 7.5, 7.5]; v.CameraViewUp = [0, 0, 1]; v.CameraViewAngle = 30
SetActiveSource(r)
Render(v)
