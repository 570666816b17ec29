# SPDX-License-Identifier: BSD-3-Clause
"""Shared pieces of the Mesolight plugin tests (pvbatch / pvpython).

The scene mirrors vtkRelief/Testing/Cxx/TestReliefAgainstDenseMesh.cxx: a procedural brick relief on the unit
square, drawn by the Relief Surface representation, against an independent reference: the same
height field as a dense displaced mesh (one vertex per texel, Mesolight Height Field Mesh) drawn
by ParaView's ordinary Surface representation, with the same camera, lights and colour.
"""
import argparse
import os
import subprocess
import sys

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403  (the plugin's proxies land here too)
import paraview.simple as pvs
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
import numpy as np

SIZE = [400, 400]
BACKGROUND = [1.0, 0.0, 1.0]  # magenta: never a grey of the white surface
DEPTH_SCALE = 0.04
# Thresholds (as in vtkRelief/Testing/Cxx/TestReliefAgainstDenseMesh.cxx): met by a correct first-hit march,
# missed by far by plain texture mapping or a flat surface.
MAX_MEAN_COLOR_ERROR = 3.0      # 8-bit levels, over pixels covered in both images
MAX_SILHOUETTE_MISMATCH = 1.0   # percent of the footprint covered by only one image


def load_plugin():
    """Loads the plugin given by MESOLIGHT_PLUGIN (the ctest environment) or argv[1]."""
    path = os.environ.get("MESOLIGHT_PLUGIN") or sys.argv[1]
    pvs.LoadPlugin(path, remote=False, ns=pvs.__dict__)
    # The tests place the camera themselves.
    pvs._DisableFirstRenderCameraReset()
    return path


def make_view():
    view = pvs.CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = BACKGROUND
    view.UseFXAA = 0
    set_camera(view)
    return view


# The tool's default camera on the Cornell box (`mesolight vlf render`; millimetres).
CORNELL_EYE, CORNELL_FOCAL, CORNELL_VIEW_ANGLE = [278.0, 273.0, -800.0], [278.0, 273.0, 0.0], 39.3077


def make_cornell_view(size):
    """A size x size view on black, without FXAA, for images compared with the tool's."""
    view = pvs.CreateView("RenderView")
    view.ViewSize = [size, size]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    view.UseFXAA = 0
    return view


def cornell_capture(view, path):
    """Renders from the tool's Cornell box camera, saves a PNG and returns it (capture_file)."""
    view.CameraPosition, view.CameraFocalPoint = CORNELL_EYE, CORNELL_FOCAL
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraViewAngle = CORNELL_VIEW_ANGLE
    pvs.Render(view)
    pvs.SaveScreenshot(path, view, ImageResolution=list(view.ViewSize), TransparentBackground=0)
    return capture_file(path)


def set_camera(view):
    view.CameraPosition = [0.5, -1.0, 1.5]
    view.CameraFocalPoint = [0.5, 0.45, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30


def relief_texture(resolution=256):
    depth = pvs.MesolightProceduralRelief(Pattern=0, Resolution=[resolution, resolution])
    return pvs.MesolightReliefTexture(Input=pvs.OutputPort(depth, 0), DepthScale=DEPTH_SCALE)


def unit_square(resolution=1):
    return pvs.Plane(Origin=[0, 0, 0], Point1=[1, 0, 0], Point2=[0, 1, 0],
                     XResolution=resolution, YResolution=resolution)


def show_relief(surface, relief, view, lights=None, **settings):
    attached = pvs.MesolightAttachReliefTexture(Input=surface, ReliefTexture=relief)
    if lights is not None:
        attached.LightSet = lights
    display = pvs.Show(attached, view)
    display.ColorArrayName = ["POINTS", ""]
    display.SetRepresentationType("Relief Surface")
    display.ReliefDepthScale = DEPTH_SCALE
    for name, value in settings.items():
        setattr(display, name, value)
    return attached, display


def show_dense_reference(relief, view):
    # Shaded with its triangles' own normals (the mesh's point normals dropped: VTK derives them
    # per fragment), as the path tracer shades it and the relief shades the surface it marches.
    mesh = pvs.PassArrays(Input=pvs.MesolightHeightFieldMesh(Input=relief))
    mesh.PointDataArrays = ["TCoords", "Depth"]
    display = pvs.Show(mesh, view)
    display.ColorArrayName = ["POINTS", ""]
    display.SetRepresentationType("Surface")
    return mesh, display


def capture(view, path):
    """Renders, saves a PNG and returns it as an H x W x 3 uint8 array."""
    set_camera(view)
    pvs.Render(view)
    pvs.SaveScreenshot(path, view, ImageResolution=SIZE, TransparentBackground=0)
    return capture_file(path)


def capture_file(path):
    """A PNG as an H x W x 3 int array."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[:, :, :3].astype(np.int32)


def eroded(mask, pixels):
    """The mask shrunk by `pixels` (edges are not compared)."""
    for _ in range(pixels):
        mask = (mask & np.roll(mask, 1, 0) & np.roll(mask, -1, 0) &
                np.roll(mask, 1, 1) & np.roll(mask, -1, 1))
    return mask


def write_obj(source, path):
    """The polygons of a pipeline output, fetched, as an OBJ file (what `mesolight vlf render
    --object` reads)."""
    mesh = servermanager.Fetch(source)
    with open(path, "w") as f:
        for p in vtk_to_numpy(mesh.GetPoints().GetData()):
            f.write("v %.6f %.6f %.6f\n" % tuple(p))
        polys = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray())
        offsets = vtk_to_numpy(mesh.GetPolys().GetOffsetsArray())
        for a, b in zip(offsets[:-1], offsets[1:]):
            f.write("f " + " ".join(str(i + 1) for i in polys[a:b]) + "\n")
    return path


REC709 = np.array([0.2126, 0.7152, 0.0722])


def cornell_field_with_object(snapshot, centre, radius):
    """The Cornell box's field (513 directions, 32 rays, 4 iterations; its snapshot written to
    `snapshot` for the reference) and a sphere moved to `centre`, gathered from it: (field, the
    moved sphere, Light Field Gather)."""
    if os.path.exists(snapshot):
        os.remove(snapshot)
    box = pvs.MesolightCornellBox()
    field = pvs.MesolightVirtualLightField(Input=box, Directions=513, RaysPerSide=32, Iterations=4,
                                           SnapshotFileName=snapshot)
    sphere = pvs.Sphere(Center=[0.0, 0.0, 0.0], Radius=radius, ThetaResolution=32,
                        PhiResolution=16)
    moved = pvs.Transform(Input=sphere)
    moved.Transform.Translate = centre
    return field, moved, pvs.MesolightLightFieldGather(Input=moved, LightField=field)


def selector_choices(display, name):
    """The pipeline outputs the Properties panel's input selector offers for `display`'s input
    property `name`, as the panel asks (ParaView 5.11, pqInputSelectorWidget::updateComboBox):
    each output port of each pipeline proxy set on the representation's prototype property, kept
    when the property's domains hold. A set of (proxy global id, port)."""
    pxm = servermanager.ProxyManager()
    smproxy = display.SMProxy
    prototype = pxm.GetPrototypeProxy(smproxy.GetXMLGroup(), smproxy.GetXMLName())
    prop = prototype.GetProperty(name)
    listed = set()
    for source in pxm.GetProxiesInGroup("sources").values():
        source = source.SMProxy if hasattr(source, "SMProxy") else source
        for port in range(source.GetNumberOfOutputPorts()):
            prop.SetInputConnection(0, source, port)
            if prop.IsInDomains():
                listed.add((source.GetGlobalIDAsString(), port))
    prop.RemoveAllProxies()
    return listed


def choice(proxy, port=0):
    """`proxy`'s output `port` as selector_choices lists it."""
    return (proxy.SMProxy.GetGlobalIDAsString(), port)


def radiance_left(with_shadow, without, region, exposure):
    """Linear luminance of `with_shadow` over that of `without` in `region` (frames clamped at
    `exposure`, sRGB): the share of the light a shadow leaves."""
    def luminance(image):
        return (srgb_decode(image)[region] / exposure) @ REC709

    return float(luminance(with_shadow).sum() / luminance(without).sum())


def object_shadow_reference(snapshot, obj_file, shadows, path, size, exposure):
    """The VTK light field actor's frame of a field snapshot with a movable object (`mesolight vlf
    render --mode progressive --object OBJ --shadows none|field`), from the Cornell box camera,
    clamped at `exposure`: the independent reference of the Shadow Caster tests."""
    command = [os.environ["MESOLIGHT_TOOL"], "vlf", "render", snapshot, "--mode", "progressive",
               "--object", obj_file, "--object-transform", "0,0,0", "--shadows", shadows,
               "--out", path, "--force", "--size", "%dx%d" % (size, size),
               "--view-angle", str(CORNELL_VIEW_ANGLE),
               "--camera", ",".join(str(c) for c in CORNELL_EYE + CORNELL_FOCAL),
               "--exposure", str(exposure), "--tone-map", "clamp"]
    print(" ".join(command))
    subprocess.run(command, check=True)
    return capture_file(path).astype(np.float64)


def covered(pixels):
    bg = (np.array(BACKGROUND) * 255).astype(np.int32)
    return np.any(np.abs(pixels - bg) > 8, axis=2)


def compare(frame, reference, footprint):
    """Mean colour error (levels) over pixels covered in both, and silhouette mismatch: % of the
    coarse surface's footprint (a boolean mask) covered by only one of the two images. As in
    the VTK tests, the dense mesh's pixels outside the footprint (the floor seen past the near
    edge, where a relief surface has no fragment to start a ray from) are not counted."""
    a, b = covered(frame) & footprint, covered(reference) & footprint
    both = a & b
    mean_error = float(np.abs(frame[both] - reference[both]).mean()) if both.any() else 255.0
    mismatch = 100.0 * float((a ^ b).sum()) / max(1, int(footprint.sum()))
    return {"mean_color_error": mean_error, "silhouette_mismatch": mismatch,
            "covered_both": int(both.sum())}


def within_tolerance(d):
    return (d["mean_color_error"] <= MAX_MEAN_COLOR_ERROR and
            d["silhouette_mismatch"] <= MAX_SILHOUETTE_MISMATCH)


def output_dir():
    out = os.environ.get("MESOLIGHT_TEST_OUTPUT", ".")
    os.makedirs(out, exist_ok=True)
    return out


def checker(failures):
    """check(ok, message): prints the message as ok or FAILED and collects the failures."""
    def check(ok, message):
        print(("ok:     " if ok else "FAILED: ") + message)
        if not ok:
            failures.append(message)
    return check


def srgb_decode(levels):
    """8-bit sRGB levels to linear values (IEC 61966-2-1)."""
    c = np.asarray(levels, dtype=np.float64) / 255.0
    return np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)


def srgb_encode(v):
    """Linear values to 8-bit sRGB levels (unrounded)."""
    v = np.clip(v, 0.0, 1.0)
    return 255.0 * np.where(v <= 0.0031308, 12.92 * v, 1.055 * v ** (1 / 2.4) - 0.055)


MAP_TOLERANCE = 1e-6


def visible_share_map(display):
    """A Relief Surface's visible-share map as the first rank holds it (LightFieldVisibleShare):
    height x width x C float32 values (C = 3, or 4 with light 0's area shadow), and the ranks its
    rows were split over."""
    display.UpdatePropertyInformation()
    values = np.asarray(display.GetPropertyValue("LightFieldVisibleShare"), dtype=np.float64)
    width, height = int(values[0]), int(values[1])
    share = values[2:].astype(np.float32).reshape(height, width, -1)
    return share, display.GetPropertyValue("LightFieldVisibleShareRanks")


def start_share_map_test():
    """The set-up of a test run once on one rank (--write-map F) and once on two (--compare-map
    F, against the first run's map; check_share_map): its options, the plugin loaded, a list of
    failures and its checker, and the rank count, which must be 2 when comparing."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--write-map")
    parser.add_argument("--compare-map")
    args, _ = parser.parse_known_args()
    load_plugin()
    failures = []
    check = checker(failures)
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    print("ranks: %d" % ranks)
    if args.compare_map:
        check(ranks == 2, "runs on two ranks")
    return args, failures, check, ranks


def check_share_map(check, display, ranks, write=None, compare=None):
    """The map split over the ranks (--write-map on one rank, --compare-map on several): its rows
    split over every rank; against the one-rank map within MAP_TOLERANCE (by construction bit for
    bit); negative: the same map with the second rank's rows (every other row) left 0, as if its
    share were not combined, must fail that check."""
    share, split = visible_share_map(display)
    display.UpdatePropertyInformation()
    print("visible-share map %d x %d over %d rank(s): %.3f s on the first rank, mean V %.4f"
          % (share.shape[1], share.shape[0], split,
             display.GetPropertyValue("LightFieldVisibleShareSeconds"),
             float(share[:, :, 0].mean())))
    check(split == ranks, "the map's rows split over the %d rank(s) (%d)" % (ranks, split))
    check(float(share[:, :, 0].min()) < 0.9, "the relief hides part of the hemisphere (min V %.3f)"
          % float(share[:, :, 0].min()))
    if write:
        np.savez(write, share=share)
        print("wrote %s" % write)
    if compare:
        one_rank = np.load(compare)["share"]

        def difference(a):
            return (float(np.abs(a.astype(np.float64) - one_rank).max())
                    if a.shape == one_rank.shape else float("inf"))

        print("map over %d ranks against one rank: max |difference| %g (bit for bit: %s)"
              % (ranks, difference(share), bool(np.array_equal(share, one_rank))))
        check(difference(share) <= MAP_TOLERANCE, "the map combined over the ranks is the "
              "one-rank map (max |difference| %g)" % difference(share))
        partial = share.copy()
        partial[1::2] = 0.0
        check(difference(partial) > MAP_TOLERANCE, "negative: without the second rank's rows the "
              "map is not the one-rank map (max |difference| %g)" % difference(partial))
