# SPDX-License-Identifier: BSD-3-Clause
"""The filters that make their whole output on every rank run once per change, also under
`mpiexec -n 2` (their executive, vtkPVWholeOutputPipeline, serves a request for any piece).

As the GUI's Apply does: each filter is updated (ParaView asks rank r for piece r of N), then
shown, so that Attach Relief Texture asks its relief texture and light set for the whole image
(piece 0 of 1). With ParaView's own executive the Relief Texture and Median Cut Lights filters ran
again for that second request on every rank: twice per change. Counted on rank 0 (the script's
rank in pvbatch) by the filters' EndEvent: one run per change. Must fail: on two ranks the same
filters as proxies that keep ParaView's executive (an XML of their own, loaded on every rank) run
more than once per change; that is checked too.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mesolight_pvtest as t  # noqa: E402
import paraview.simple as pvs  # noqa: E402
from paraview import servermanager  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand  # noqa: E402

t.load_plugin()
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
failures = []
check = t.checker(failures)


def count_runs(proxy):
    runs = []
    proxy.GetClientSideObject().AddObserver(vtkCommand.EndEvent, lambda *_: runs.append(1))
    return runs


# The same two filters as proxies that keep ParaView's own executive (no executive attribute):
# loaded on every rank, like the plugin's own XML.
PARAVIEW_EXECUTIVE_XML = """<ServerManagerConfiguration>
  <ProxyGroup name="filters">
    <SourceProxy name="ReliefTextureParaViewExecutive" class="vtkReliefTextureFilter">
      <InputProperty name="Input" command="SetInputConnection"/>
      <DoubleVectorProperty name="DepthScale" command="SetDepthScale" number_of_elements="1"
                            default_values="0.05"/>
    </SourceProxy>
    <SourceProxy name="MedianCutLightsParaViewExecutive" class="vtkMedianCutLights">
      <InputProperty name="Input" command="SetInputConnection"/>
      <IntVectorProperty name="NumberOfLights" command="SetNumberOfLights" number_of_elements="1"
                         default_values="64"/>
      <OutputPort name="Lights" index="0"/>
      <OutputPort name="LightTexture" index="1"/>
    </SourceProxy>
  </ProxyGroup>
</ServerManagerConfiguration>
"""


def apply_and_show(paraview_executive):
    """Two changes, each applied as the GUI applies them; returns the runs per filter."""
    depth = pvs.MesolightProceduralRelief(Pattern=0, Resolution=[64, 64])
    environment = pvs.MesolightProceduralEnvironment(Resolution=[64, 32])
    if paraview_executive:
        relief = globals()["ReliefTextureParaViewExecutive"](Input=pvs.OutputPort(depth, 0))
        lights = globals()["MedianCutLightsParaViewExecutive"](Input=environment)
    else:
        relief = pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0))
        lights = pvs.MesolightMedianCutLights(Input=environment)
    runs = {"Relief Texture": count_runs(relief), "Median Cut Lights": count_runs(lights)}
    view = t.make_view()
    plane = t.unit_square()
    for change in range(2):
        relief.DepthScale = 0.05 + 0.05 * change
        lights.NumberOfLights = 16 + 16 * change
        for proxy in (depth, relief, environment, lights, plane):
            proxy.UpdatePipeline()
        if change == 0:
            t.show_relief(plane, relief, view, lights=pvs.OutputPort(lights, 1))
        pvs.Render(view)
        pvs.Render(view)
    return {name: len(r) for name, r in runs.items()}


runs = apply_and_show(paraview_executive=False)
for name, count in runs.items():
    print("%d rank(s), %s: %d run(s) for 2 changes" % (ranks, name, count))
    check(count == 2, "%s runs once per change" % name)
if ranks > 1:
    definitions = os.path.join(t.output_dir(), "paraview-executive-filters.xml")
    with open(definitions, "w") as f:
        f.write(PARAVIEW_EXECUTIVE_XML)
    pvs.LoadPlugin(definitions, remote=True, ns=globals())
    before = apply_and_show(paraview_executive=True)
    for name, count in before.items():
        print("%d ranks, %s with ParaView's executive: %d run(s) for 2 changes"
              % (ranks, name, count))
        check(count > 2, "%s with ParaView's executive runs more than once per change" % name)

if failures:
    print("FAILED: " + "; ".join(failures))
    sys.exit(1)
print("OK")
