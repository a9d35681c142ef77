"""Run by run-gui-test.sh in the ParaView GUI (--script): shows the tiny volume as VisSweep Volume
with SamplesPerFrame 4 and MaximumSamples 12 and renders once; the plugin's refinement timer must
take it to 12 samples per pixel with no further render asked for."""
from paraview.simple import *
import os
LoadPlugin(os.environ["VS_PLUGIN"], remote=False, ns=globals())
r = XMLImageDataReader(FileName=[os.environ["VS_VOLUME"]])
v = GetActiveViewOrCreate("RenderView")
d = Show(r, v); d.Representation = "VisSweep Volume"; ColorBy(d, ("POINTS", "density"))
d.SamplesPerFrame = 4; d.MaximumSamples = 12
v.ResetCamera()
Render(v)
d.UpdatePropertyInformation()
print("after the script's one render:", d.GetPropertyValue("AccumulatedSamples"), "spp", flush=True)
