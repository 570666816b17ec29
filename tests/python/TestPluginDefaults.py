# SPDX-License-Identifier: BSD-3-Clause
"""The ParaView plugin's XML defaults are the filters' own.

ParaView pushes every property's default_values onto a new filter, so a value in
paraview_plugin/Plugin/*.xml that differs from the class's C++ default silently overrides it
for every ParaView user (a filter that chose its resolution automatically would get the XML's
fixed one instead). For each SourceProxy whose class the `mesolight` package has, each
Int/DoubleVectorProperty with a Set command, a matching Get and one default value: the XML's
default must equal what a new instance returns. Prints every property checked; exits 1 listing
the mismatches, when nothing was checked, or when the negative case (the light field filter's
XML with its Directions default changed) goes unnoticed.

    scripts/python.sh tests/python/TestPluginDefaults.py paraview_plugin/Plugin/*.xml
"""
import sys
import xml.etree.ElementTree as ElementTree

import mesolight


def main(paths):
    checked, mismatches = 0, []
    for path in paths:
        for proxy in ElementTree.parse(path).getroot().iter("SourceProxy"):
            cls = getattr(mesolight, proxy.get("class", ""), None)
            if cls is None:
                continue
            instance = cls()
            for prop in proxy:
                if prop.tag not in ("IntVectorProperty", "DoubleVectorProperty"):
                    continue
                command = prop.get("command", "")
                default = prop.get("default_values")
                if (not command.startswith("Set") or default is None or prop.get("information_only") == "1"
                        or len(default.split()) != 1):
                    continue
                getter = getattr(instance, "Get" + command[3:], None)
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
                      f"{proxy.get('class')}.{getter.__name__}() {actual}{'' if ok else '  MISMATCH'}")
                checked += 1
                if not ok:
                    mismatches.append(f"{proxy.get('name')}.{prop.get('name')}")
    print(f"{checked} defaults checked, {len(mismatches)} differ from the C++ defaults")
    if mismatches:
        print("differ:", ", ".join(mismatches))
        return 1
    return 0 if checked > 0 else 1


def negative_case(directory):
    """The check must notice a wrong default: the filter's XML with Directions' default changed."""
    import os
    import re
    source = None
    for path in sys.argv[1:]:
        text = open(path).read()
        if 'class="vtkVirtualLightField"' in text:
            source = text
    if source is None:
        return True  # no light field XML given: nothing to break
    broken = re.sub(r'(name="Directions" command="SetDirections"[^>]*default_values=")\d+"',
                    r'\g<1>2049"', source, count=1)
    path = os.path.join(directory, "broken.xml")
    with open(path, "w") as out:
        out.write(broken)
    failed = main([path]) == 1
    print("negative case (Directions default 2049 in the XML): %s" % ("caught" if failed else "MISSED"))
    return failed


if __name__ == "__main__":
    import tempfile
    status = main(sys.argv[1:])
    with tempfile.TemporaryDirectory() as work:
        if not negative_case(work):
            status = 1
    sys.exit(status)
