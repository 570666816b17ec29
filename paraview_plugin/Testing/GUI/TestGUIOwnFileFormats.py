# SPDX-License-Identifier: BSD-3-Clause
"""GUI: the README pipeline on a user's own depth image in each format (16-bit PNG, 8-bit JPEG,
float TIFF, float OpenEXR; the 8-bit PNG is TestGUIOwnFiles.xml's) and own HDR environment
(sky.hdr), each opened by a reader ParaView offers for it (for .png, .jpg and .tif File > Open
asks: the PNG and TIFF Series Readers, and for every one the Mesolight Image Reader, which the
JPEG takes; GDAL Raster Reader, also offered, gives the pixels as cells, which Relief Texture
reads at their corners, docs/paraview.md; .exr and .hdr: OpenDataFile, the reader factory's
choice), in
the orders a user may apply the steps, each step applied as the GUI applies it
(mesolight_guitest.apply). After the last Apply the relief must be the only visible data (every
image hidden), in 3D, framed. Must fail: the same run with the plugin's hiding turned off
leaves the images shown (checked by hand, docs/paraview.md)."""
import os

import mesolight_guitest as g
import mesolight_ownfiles as own
import mesolight_xmltest as x
import paraview.simple as pvs

ORDERS = {
    # depth, relief texture, plane, attach (light set given at creation)
    "depth first, lights first": ["sky", "cut", "depth", "relief", "plane", "attach"],
    # plane first, the environment last and attached by a second Apply
    "plane first, lights last": ["plane", "depth", "relief", "attach", "sky", "cut", "light set"],
}


def run_order(view, depth_file, steps):
    made = {}
    for step in steps:
        if step == "sky":
            made[step] = pvs.OpenDataFile(os.path.join(own.directory(), "sky.hdr"))
        elif step == "cut":
            made[step] = pvs.MesolightMedianCutLights(Input=made["sky"], NumberOfLights=16)
        elif step == "depth":
            path = os.path.join(own.directory(), depth_file)
            if depth_file.endswith(".jpg"):
                made[step] = pvs.MesolightImageReader(FileName=path)
            elif depth_file.endswith(".png"):
                made[step] = pvs.PNGSeriesReader(FileNames=[path])
            elif depth_file.endswith(".tif"):
                made[step] = pvs.TIFFSeriesReader(FileNames=[path])
            else:
                made[step] = pvs.OpenDataFile(path)
        elif step == "relief":
            made[step] = pvs.MesolightReliefTexture(Input=made["depth"])
        elif step == "plane":
            made[step] = pvs.Plane()
        elif step == "attach":
            made[step] = pvs.MesolightAttachReliefTexture(Input=made["plane"],
                                                          ReliefTexture=made["relief"])
            if "cut" in made:
                made[step].LightSet = pvs.OutputPort(made["cut"], 1)
        if step == "light set":
            made["attach"].LightSet = pvs.OutputPort(made["cut"], 1)
            pvs.SetActiveSource(made["attach"])
            pvs.Render(view)  # a later Apply: the pipeline updates, nothing new is shown
        else:
            g.apply(made[step], view)
    return made


@x._guarded
def mesolight_reader_offered(extensions):
    """File > Open's file types: the Mesolight Image Reader claims the 8/16-bit formats beside
    ParaView's own readers, so the reader dialog offers it for them (it gives point scalars), and
    SRTM height tiles (.hgt), which no other reader opens."""
    factory = pvs.servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    factory.UpdateAvailableReaders()
    types = factory.GetSupportedFileTypes(pvs.servermanager.ActiveConnection.Session).split(";;")
    ours = [t for t in types if t.startswith("Images (OpenImageIO, Mesolight)")]
    missing = [e for e in extensions if not ours or "*.%s" % e not in ours[0].split("(")[-1]]
    x._check(not missing, "Mesolight Image Reader's file types %s lack %s" % (ours, missing))


def main():
    own.write_files()
    mesolight_reader_offered(["png", "jpg", "jpeg", "tif", "tiff", "exr", "hdr", "hgt"])
    view = g.gui_view()
    readers = {}
    # Each format once, the orders alternating (the suite's time: about 13 s a run here).
    orders = list(ORDERS.items())
    for k, depth_file in enumerate(("depth16.png", "depth.jpg", "depth.tif", "depth.exr")):
        for name, steps in [orders[k % len(orders)]]:
            made = run_order(view, depth_file, steps)
            readers[depth_file] = made["depth"].GetXMLLabel()
            readers["sky.hdr"] = made["sky"].GetXMLLabel()
            x._print("%s, %s (read by %s, sky by %s):"
                     % (depth_file, name, readers[depth_file], readers["sky.hdr"]))
            own.only_relief_framed()
            own.light_set_port(1)
            for proxy in reversed(list(made.values())):
                pvs.Delete(proxy)
    x._print("readers ParaView picked: %s" % readers)
    return list(x._failures)


g.run(main)
