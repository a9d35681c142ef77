"""Run by run-gui-test.sh in the ParaView GUI (--script): shows the tiny volume as VisSweep Volume
with SamplesPerFrame 4 and MaximumSamples 12 and renders once; the plugin's refinement timer must
take it to 12 samples per pixel with no further render asked for. With VS_REMOTE=1 the GUI is the
client of a pvserver: the plugin is loaded on both sides and the server renders."""
from paraview.simple import *
import os
if os.environ.get("VS_REMOTE") == "1":
    LoadPlugin(os.environ["VS_PLUGIN"], remote=True, ns=globals())
LoadPlugin(os.environ["VS_PLUGIN"], remote=False, ns=globals())
r = XMLImageDataReader(FileName=[os.environ["VS_VOLUME"]])
v = GetActiveViewOrCreate("RenderView")
d = Show(r, v); d.Representation = "VisSweep Volume"; ColorBy(d, ("POINTS", "density"))
d.SamplesPerFrame = 4; d.MaximumSamples = 12
v.ResetCamera()
Render(v)
d.UpdatePropertyInformation()
print("after the script's one render:", d.GetPropertyValue("AccumulatedSamples"), "spp", flush=True)
