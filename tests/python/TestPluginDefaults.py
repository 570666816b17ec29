# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView plugin's XML defaults are the filters' own.

ParaView pushes every property's default_values onto a new filter, so a value in
paraview_plugin/Plugin/*.xml that differs from the class's C++ default silently overrides it
for every ParaView user (a filter that chose its resolution automatically would get the XML's
fixed one instead). For each SourceProxy whose class the `mesolight` package has, each
Int/DoubleVectorProperty with a Set command, a matching Get and one default value: the XML's
default must equal what a new instance returns; the same for the Relief Surface representation's
properties against a new vtkReliefProperty (the representation forwards them to one). Prints
every property checked; exits 1 listing the mismatches, when nothing was checked, or when a
negative case (the light field filter's Directions default, the representation's FarViewRays
default changed in the XML) goes unnoticed.

    scripts/python.sh tests/python/TestPluginDefaults.py paraview_plugin/Plugin/*.xml
"""
import sys
import xml.etree.ElementTree as ElementTree

import mesolight


# The Relief Surface representation forwards its relief settings to a vtkReliefProperty
# (vtkReliefSurfaceRepresentation): its XML defaults must be that class's. Setter names that
# differ from the property's.
RELIEF_REPRESENTATION = "MesolightReliefSurfaceRepresentation"
RELIEF_REPRESENTATION_GETTERS = {"SetReliefMethod": "GetMethod", "SetReliefDepthScale": "GetDepthScale"}


def proxies(root):
    """(proxy element, instance of the class whose defaults it must have, setter -> getter names)."""
    for proxy in root.iter("SourceProxy"):
        cls = getattr(mesolight, proxy.get("class", ""), None)
        if cls is not None:
            yield proxy, cls(), {}
    for proxy in root.iter("ReliefSurfaceRepresentationProxy"):
        if proxy.get("name") == RELIEF_REPRESENTATION:
            yield proxy, mesolight.vtkReliefProperty(), RELIEF_REPRESENTATION_GETTERS


def main(paths):
    checked, mismatches = 0, []
    for path in paths:
        for proxy, instance, getters in proxies(ElementTree.parse(path).getroot()):
            for prop in proxy:
                if prop.tag not in ("IntVectorProperty", "DoubleVectorProperty"):
                    continue
                command = prop.get("command", "")
                default = prop.get("default_values")
                if (not command.startswith("Set") or default is None or prop.get("information_only") == "1"
                        or len(default.split()) != 1):
                    continue
                getter = getattr(instance, getters.get(command, "Get" + command[3:]), None)
                if getter is None:
                    continue
                try:
                    actual = getter()
                except TypeError:
                    continue  # a getter that takes an argument is not the property's value
                if not isinstance(actual, (int, float, bool)):
                    continue
                expected = float(default)
                ok = abs(float(actual) - expected) <= 1e-9 * max(1.0, abs(expected))
                print(f"{proxy.get('name')}.{prop.get('name')}: XML {default}, "
                      f"{type(instance).__name__}.{getter.__name__}() {actual}"
                      f"{'' if ok else '  MISMATCH'}")
                checked += 1
                if not ok:
                    mismatches.append(f"{proxy.get('name')}.{prop.get('name')}")
    print(f"{checked} defaults checked, {len(mismatches)} differ from the C++ defaults")
    if mismatches:
        print("differ:", ", ".join(mismatches))
        return 1
    return 0 if checked > 0 else 1


def broken_default_caught(directory, marker, name, command, value):
    """The check must notice a wrong default: the XML holding `marker` with property `name`'s
    default changed to `value`."""
    import os
    import re
    source = None
    for path in sys.argv[1:]:
        text = open(path).read()
        if marker in text:
            source = text
    if source is None:
        return True  # that XML not given: nothing to break
    broken = re.sub(r'(name="%s" command="%s"[^>]*default_values=")\d+"' % (name, command),
                    r'\g<1>%s"' % value, source, count=1)
    path = os.path.join(directory, "broken.xml")
    with open(path, "w") as out:
        out.write(broken)
    failed = main([path]) == 1
    print("negative case (%s default %s in the XML): %s" % (name, value, "caught" if failed else "MISSED"))
    return failed


if __name__ == "__main__":
    import tempfile
    status = main(sys.argv[1:])
    with tempfile.TemporaryDirectory() as work:
        if not broken_default_caught(work, 'class="vtkVirtualLightField"', "Directions",
                                     "SetDirections", 2049):
            status = 1
        if not broken_default_caught(work, 'name="%s"' % RELIEF_REPRESENTATION, "FarViewRays",
                                     "SetFarViewRays", 5):
            status = 1
    sys.exit(status)
