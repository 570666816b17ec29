# SPDX-License-Identifier: BSD-3-Clause
# The bump geometry image (256^2) sampled every 12 pixels and adaptively to 0.002, drawn with edges
# (docs/geometry-images.md). Run:
#   scripts/pvbatch.sh docs/measurements/geometry-images/bump-meshes.py
# then oiiotool mesh-regular.png mesh-adaptive.png --mosaic 2x1 -o bump-regular-vs-adaptive-mesh.png
import paraview.simple as pvs
pvs._DisableFirstRenderCameraReset()
bump = pvs.MesolightGeometryImage(Surface=4, Resolution=[256, 256])
for name, props in [("regular", dict(Stride=12)), ("adaptive", dict(Tolerance=0.002))]:
    mesh = pvs.MesolightGeometryImageToMesh(Input=bump, **props)
    view = pvs.CreateView("RenderView")
    view.ViewSize = [360, 300]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    d = pvs.Show(mesh, view)
    d.SetRepresentationType("Surface With Edges")
    d.ColorArrayName = ["POINTS", ""]
    d.DiffuseColor = [0.85, 0.75, 0.6]
    d.EdgeColor = [0.1, 0.1, 0.2]
    view.CameraPosition = [0.5, -0.9, 1.3]
    view.CameraFocalPoint = [0.5, 0.5, -0.05]
    view.CameraViewUp = [0, 0, 1]
    view.CameraViewAngle = 30
    pvs.Render(view)
    print(name, pvs.servermanager.Fetch(mesh).GetNumberOfCells())
    pvs.SaveScreenshot("mesh-%s.png" % name, view, ImageResolution=[360, 300])
