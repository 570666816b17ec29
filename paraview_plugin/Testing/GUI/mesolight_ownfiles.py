# SPDX-License-Identifier: BSD-3-Clause
"""A user's own files in the GUI: the test writes them itself (no procedural source) into
$PARAVIEW_TEST_DIR, which the QtTesting file dialog events name $PARAVIEW_TEST_ROOT, and checks
what the view shows after each Apply. Used by TestGUIOwnFiles.xml (the real Apply button, File >
Open) and TestGUIOwnFileFormats.py.

Depth images: a dome and a groove (0 = surface, 1 = deepest) as an 8-bit PNG, a 16-bit PNG, an
8-bit JPEG, a float TIFF and a float OpenEXR (oiiotool, from openimageio-tools); the environment: a lat-long
Radiance HDR (written here, uncompressed RGBE scanlines) with a bright sun patch, and the same sky
as a float RGB TIFF."""
import math
import os
import struct
import subprocess

import mesolight_guitest as g
import mesolight_xmltest as x
import numpy as np
import paraview.simple as pvs
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkJPEGWriter, vtkPNGWriter, vtkTIFFWriter

SIZE = 128


def directory():
    path = os.environ.get("PARAVIEW_TEST_DIR") or g.output_dir()
    os.makedirs(path, exist_ok=True)
    return path


def depth_map():
    y, x_ = np.mgrid[0:SIZE, 0:SIZE].astype(np.float64) / (SIZE - 1)
    r = np.hypot(x_ - 0.35, y - 0.5)
    dome = np.clip(1.0 - (r / 0.25) ** 2, 0.0, 1.0)
    groove = np.exp(-((x_ - 0.78) / 0.06) ** 2)
    return np.clip(0.6 * (1.0 - dome) + 0.4 * groove, 0.0, 1.0)


def _image(values, vtk_type=None, name="depth"):
    """An image of `values` (rows bottom up; a third axis: the components)."""
    image = vtkImageData()
    image.SetDimensions(values.shape[1], values.shape[0], 1)
    components = values.shape[2] if values.ndim == 3 else 1
    array = numpy_to_vtk(np.ascontiguousarray(values.reshape(-1, components).squeeze()), deep=1,
                         array_type=vtk_type)
    array.SetName(name)
    image.GetPointData().SetScalars(array)
    return image


def write_png(path, bits):
    from vtkmodules.util.vtkConstants import VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT
    top = 255 if bits == 8 else 65535
    values = np.round(depth_map() * top).astype(np.uint8 if bits == 8 else np.uint16)
    writer = vtkPNGWriter()
    writer.SetInputData(_image(values, VTK_UNSIGNED_CHAR if bits == 8 else VTK_UNSIGNED_SHORT))
    writer.SetFileName(path)
    writer.Write()


def write_jpeg(path):
    from vtkmodules.util.vtkConstants import VTK_UNSIGNED_CHAR
    writer = vtkJPEGWriter()
    writer.SetInputData(_image(np.round(depth_map() * 255).astype(np.uint8), VTK_UNSIGNED_CHAR))
    writer.SetQuality(95)
    writer.SetFileName(path)
    writer.Write()


def write_tiff(path, depth=None):
    writer = vtkTIFFWriter()
    writer.SetInputData(_image((depth_map() if depth is None else depth).astype(np.float32)))
    writer.SetFileName(path)
    writer.Write()


def write_exr(path):
    """Through a float TIFF and oiiotool (OpenEXR needs a library ParaView's VTK lacks)."""
    tiff = path + ".tif"
    write_tiff(tiff)
    subprocess.run(["oiiotool", tiff, "-d", "float", "-o", path], check=True)
    os.remove(tiff)


def sky_pixel(i, j, width, height):
    """Pixel (i, j) of a lat-long sky with a sun, row j = 0 the zenith's (a file's top row)."""
    theta = math.pi * (j + 0.5) / height
    phi = 2 * math.pi * (i + 0.5) / width
    sky = 0.4 + 0.6 * max(0.0, math.cos(theta))
    sun = 40.0 if abs(theta - 0.8) < 0.12 and abs(phi - 1.0) < 0.12 else 0.0
    return (sky + sun, sky * 0.95 + sun, sky * 1.1 + sun)


def write_hdr(path, width=128, height=64):
    """The sky: Radiance RGBE, flat (uncompressed) scanlines, top row first."""
    rows = []
    for j in range(height):
        for i in range(width):
            rgb = sky_pixel(i, j, width, height)
            top = max(rgb)
            mantissa, exponent = math.frexp(top)
            scale = mantissa * 256.0 / top
            rows.append(struct.pack("BBBB", *(int(c * scale) for c in rgb), exponent + 128))
    with open(path, "wb") as f:
        f.write(b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y %d +X %d\n" % (height, width))
        f.write(b"".join(rows))


def write_sky_tiff(path, width=128, height=64):
    """The sky as a float RGB TIFF (VTK's rows bottom up: the zenith's row last)."""
    rgb = np.array([[sky_pixel(i, height - 1 - j, width, height) for i in range(width)]
                    for j in range(height)], dtype=np.float32)
    writer = vtkTIFFWriter()
    writer.SetInputData(_image(rgb, name="sky"))
    writer.SetFileName(path)
    writer.Write()


def write_files():
    d = directory()
    write_png(os.path.join(d, "depth.png"), 8)
    write_png(os.path.join(d, "depth16.png"), 16)
    write_jpeg(os.path.join(d, "depth.jpg"))
    write_tiff(os.path.join(d, "depth.tif"))
    write_exr(os.path.join(d, "depth.exr"))
    write_hdr(os.path.join(d, "sky.hdr"))
    write_sky_tiff(os.path.join(d, "sky.tif"))
    x._print("wrote the user's files into %s" % d)


@x._guarded
def only_relief_framed(min_span=0.5):
    """After the last Apply: the relief the only visible data (every image hidden, whatever
    reader opened it), 3D interaction, framed."""
    view = g.gui_view()
    visible = sorted(r.Input.GetXMLName() for r in g.visible_data_representations(view))
    x._check(visible == ["MesolightAttachReliefTexture"],
             "visible data after the last Apply: %s (only the relief expected)" % visible)
    x.interaction_mode("3D", "after the last Apply")
    x.relief_shown_framed(min_span)


@x._guarded
def attached_to(expected):
    """The proxy type of Attach Relief Texture's Input (the surface the relief is drawn on)."""
    surface = x.source("MesolightAttachReliefTexture").Input
    name = surface.GetXMLName() if surface is not None else None
    x._check(name == expected, "Attach Relief Texture's Input: %s (expected %s)" % (name, expected))


@x._guarded
def light_set_port(expected):
    """Attach Relief Texture's Light Set: the producer's output port (1: LightTexture)."""
    prop = x.source("MesolightAttachReliefTexture").LightSet
    port = getattr(prop, "Port", None) if prop is not None else None
    x._check(port == expected, "Light Set from output port %s (expected %s)" % (port, expected))


@x._guarded
def visible(expected, when):
    """The proxy types of the visible data, sorted."""
    shown = sorted(r.Input.GetXMLName() for r in g.visible_data_representations(g.gui_view()))
    x._check(shown == sorted(expected), "visible data %s: %s (expected %s)"
             % (when, shown, sorted(expected)))
