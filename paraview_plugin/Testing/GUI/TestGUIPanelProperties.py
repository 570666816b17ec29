# SPDX-License-Identifier: BSD-3-Clause
"""GUI: every property of every Mesolight proxy (listed from Plugin/*.xml) is in the Properties
panel, or deliberately not (listed in DELIBERATE with the reason, as in docs/paraview.md).

A property reaches the panel of ParaView 5.11 (pqProxyWidget::createWidgetForProperty) when it
is an Int, Double or String vector property (IdTypeVectorProperty has no widget), not
panel_visibility="never", not information-only, and -- for a representation's properties --
exposed to the geometry representation (<ExposedProperties>). Each property also needs a
documentation string (the panel's tooltip) and must exist on the proxy the GUI session loaded."""
import glob
import os
import sys
import xml.etree.ElementTree as ET

# run-gui-test.sh puts this directory on PYTHONPATH (paraview --script defines no __file__).
import mesolight_guitest as g  # noqa: E402
from paraview import servermanager as sm  # noqa: E402

# (proxy, property): why it is not a panel widget.
DELIBERATE = {
    ("MesolightImageReader", "FileName"): "set by File > Open",
    ("MesolightOBJSceneReader", "FileName"): "set by File > Open",
    ("MesolightOBJSceneReader", "NonManifoldEdges"):
        "information about the last read (Python: GetPropertyValue)",
    ("MesolightOBJSceneReader", "DegenerateTriangles"):
        "information about the last read (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightSetAttached"):
        "set from the data by the proxy class; the panel's decorators read it",
    ("MesolightReliefSurfaceRepresentation", "LightFieldAttached"):
        "set from the Light Field input by the proxy class; the panel's decorators read it",
    ("MesolightReliefSurfaceRepresentation", "ReliefShadowMode"):
        "follows the field display's Shadow Mode (the proxy class; Python: ReliefShadowMode)",
    ("MesolightReliefSurfaceRepresentation", "ReliefShadowMapResolution"):
        "follows the field display's Shadow Map Resolution (the proxy class; Python: "
        "ReliefShadowMapResolution)",
    ("MesolightVirtualLightField", "DirectionsPropagated"):
        "information about the last update (Python: GetPropertyValue)",
    ("MesolightLightFieldGather", "FieldPropagations"):
        "information about the last update (Python: GetPropertyValue)",
    ("MesolightLightFieldGather", "FieldBroadcasts"):
        "information about the last update (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightFieldProbeGatherings"):
        "information about the last updates (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightFieldVisibleShareMaps"):
        "information about the last updates (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightFieldVisibleShare"):
        "information about the last updates (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightFieldVisibleShareRanks"):
        "information about the last updates (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightFieldVisibleShareSeconds"):
        "information about the last updates (Python: GetPropertyValue)",
    ("MesolightReliefSurfaceRepresentation", "LightFieldVisibleShareCpuSeconds"):
        "information about the last updates (Python: GetPropertyValue)",
}
# ReliefSurfaceRepresentationProxy: a representation with its own client-side proxy class.
REPRESENTATION_TAGS = ("RepresentationProxy", "ReliefSurfaceRepresentationProxy")
PANEL_TYPES = ("IntVectorProperty", "DoubleVectorProperty", "StringVectorProperty")


def exposed_representation_properties(root):
    names = set()
    for ext in root.iter("Extension"):
        for prop in ext.iter("Property"):
            names.add(prop.get("name"))
    return names


def main():
    failures = []
    xml_dir = os.environ["MESOLIGHT_PLUGIN_XML_DIR"]
    pxm = sm.ProxyManager()
    counted = 0
    for path in sorted(glob.glob(os.path.join(xml_dir, "*.xml"))):
        root = ET.parse(path).getroot()
        exposed = exposed_representation_properties(root)
        for group in root.iter("ProxyGroup"):
            for proxy in group:
                if proxy.tag not in ("SourceProxy", "Proxy") + REPRESENTATION_TAGS:
                    continue
                pname = proxy.get("name")
                prototype = pxm.SMProxyManager.GetPrototypeProxy(group.get("name"), pname)
                if prototype is None:
                    failures.append("%s: not loaded in the GUI session" % pname)
                    continue
                for prop in proxy:
                    if not prop.tag.endswith("Property"):
                        continue
                    name = prop.get("name")
                    counted += 1
                    where = "%s.%s (%s)" % (pname, name, os.path.basename(path))
                    if prototype.GetProperty(name) is None:
                        failures.append("%s: missing on the GUI's proxy" % where)
                    doc = prop.find("Documentation")
                    if doc is None or not "".join(doc.itertext()).strip():
                        failures.append("%s: no documentation (the panel's tooltip)" % where)
                    reason = DELIBERATE.get((pname, name))
                    if prop.tag == "InputProperty":
                        reason = reason or "an input: chosen when the filter is created"
                    if reason:
                        print("deliberately not a panel widget: %s: %s" % (where, reason))
                        continue
                    if prop.tag not in PANEL_TYPES:
                        failures.append("%s: a %s has no widget in ParaView 5.11's panel"
                                        % (where, prop.tag))
                    if prop.get("information_only") == "1":
                        failures.append("%s: information-only, not in the panel" % where)
                    if prop.get("panel_visibility") == "never":
                        failures.append("%s: panel_visibility never, undocumented" % where)
                    if proxy.tag in REPRESENTATION_TAGS and name not in exposed:
                        failures.append("%s: not exposed to the geometry representation" % where)
    print("%d properties checked" % counted)
    if counted < 50:
        failures.append("only %d properties found in %s" % (counted, xml_dir))
    return failures


g.run(main)
