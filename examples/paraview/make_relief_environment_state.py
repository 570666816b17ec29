# SPDX-License-Identifier: BSD-3-Clause
"""Builds examples/relief-environment.pvsm: a stone relief on a square, lit only by the default
procedural environment (a smooth sky) through 64 median-cut lights, shown with the Relief
Surface representation. Run with the plugin's pvbatch (see docs/paraview.md):

    scripts/pvbatch.sh examples/paraview/make_relief_environment_state.py [OUT.pvsm] [OUT.png]
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
import paraview.simple as pvs

here = os.path.dirname(os.path.abspath(__file__))
state = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "relief-environment.pvsm")
plugin = os.environ.get("MESOLIGHT_PLUGIN")
if plugin:
    pvs.LoadPlugin(plugin, remote=False, ns=pvs.__dict__)
pvs._DisableFirstRenderCameraReset()

depth = pvs.MesolightProceduralRelief(registrationName="Stone depth", Pattern=1, Resolution=[256, 256])
relief = pvs.MesolightReliefTexture(registrationName="Relief texture",
                                    Input=pvs.OutputPort(depth, 0), DepthScale=0.05)
sky = pvs.MesolightProceduralEnvironment(registrationName="Default environment (sky)")
lights = pvs.MesolightMedianCutLights(registrationName="Median cut lights", Input=sky,
                                      NumberOfLights=64)
plane = pvs.Plane(registrationName="Surface", Origin=[0, 0, 0], Point1=[1, 0, 0], Point2=[0, 1, 0])
attached = pvs.MesolightAttachReliefTexture(registrationName="Relief surface", Input=plane,
                                            ReliefTexture=relief)
attached.LightSet = pvs.OutputPort(lights, 1)

view = pvs.GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 600]
view.OrientationAxesVisibility = 0
view.UseLight = 0  # no light kit: the environment's lights only
view.CameraPosition = [0.5, -0.9, 1.0]
view.CameraFocalPoint = [0.5, 0.45, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.CameraViewAngle = 30

display = pvs.Show(attached, view)
display.ColorArrayName = ["POINTS", ""]
display.SetRepresentationType("Relief Surface")
display.ReliefDepthScale = 0.05
display.LinearSteps = 16
display.Exposure = 1.0
display.ToneMapping = 1

pvs.Render(view)
pvs.SaveState(state)
print("wrote " + os.path.abspath(state))
if len(sys.argv) > 2:
    pvs.SaveScreenshot(sys.argv[2], view, ImageResolution=[800, 600])
