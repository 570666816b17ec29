# SPDX-License-Identifier: BSD-3-Clause
"""Builds examples/photographs-to-model.pvsm: from two photographs of a stone wall
(examples/data/photographs: overcast and flash, path-traced by `mesolight bench hallucinate
--maps Stone --size 96 --photos DIR`) to a relit model. Depth hallucination gives the depth map,
the Relief Texture filter bakes it, a cylinder's geometry image becomes the coarse mesh, and the
relief on it, coloured by the hallucinated albedo, is lit only by 64 median-cut lights of the built-in sun and sky (Relief Surface
representation), with soft self-shadows. Run with the plugin's pvbatch (see docs/paraview.md):

    scripts/pvbatch.sh examples/paraview/make_photographs_to_model_state.py [OUT.pvsm] [OUT.png]

ParaView stores the photographs' absolute paths; when the state is loaded from another checkout,
choose "Search files under specified directory" (examples/data/photographs) in the GUI, or
LoadState(FILE, data_directory=...) in Python.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
import paraview.simple as pvs

here = os.path.dirname(os.path.abspath(__file__))
state = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "photographs-to-model.pvsm")
photographs = os.path.normpath(os.path.join(here, "..", "data", "photographs"))
plugin = os.environ.get("MESOLIGHT_PLUGIN")
if plugin:
    pvs.LoadPlugin(plugin, remote=False, ns=pvs.__dict__)
pvs._DisableFirstRenderCameraReset()

diffuse = pvs.MesolightImageReader(registrationName="stone-diffuse.exr",
                                   FileName=os.path.join(photographs, "stone-diffuse.exr"))
flash = pvs.MesolightImageReader(registrationName="stone-flash.exr",
                                 FileName=os.path.join(photographs, "stone-flash.exr"))
hallucination = pvs.MesolightDepthHallucination(registrationName="Depth hallucination",
                                                Input=diffuse, Flash=flash)
relief = pvs.MesolightReliefTexture(registrationName="Relief texture",
                                    Input=pvs.OutputPort(hallucination, 1), DepthScale=0.05)
geometry = pvs.MesolightGeometryImage(registrationName="Cylinder geometry image", Surface=1)
mesh = pvs.MesolightGeometryImageToMesh(registrationName="Macro mesh", Input=geometry, Stride=8)
sky = pvs.MesolightProceduralEnvironment(registrationName="Sun and sky", Map=1, SunElevation=25.0)
lights = pvs.MesolightMedianCutLights(registrationName="Median cut lights", Input=sky,
                                      NumberOfLights=64)
attached = pvs.MesolightAttachReliefTexture(registrationName="Relief model", Input=mesh,
                                            ReliefTexture=relief,
                                            ColorTexture=pvs.OutputPort(hallucination, 0))
attached.LightSet = pvs.OutputPort(lights, 1)

view = pvs.GetActiveViewOrCreate("RenderView")
view.ViewSize = [600, 600]
view.OrientationAxesVisibility = 0
view.UseLight = 0  # no light kit: the environment's lights only
view.Background = [0.08, 0.08, 0.1]
view.UseColorPaletteForBackground = 0
display = pvs.Show(attached, view)
display.ColorArrayName = ["POINTS", ""]
display.SetRepresentationType("Relief Surface")
display.LinearSteps = 16
display.ToneMapping = 1
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Elevation(20.0)
camera.Zoom(1.3)

pvs.Render(view)
pvs.SaveState(state)
print("wrote " + os.path.abspath(state))
if len(sys.argv) > 2:
    pvs.SaveScreenshot(sys.argv[2], view, ImageResolution=[600, 600])
    print("wrote " + os.path.abspath(sys.argv[2]))
