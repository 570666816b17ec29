# SPDX-License-Identifier: BSD-3-Clause
"""The `mesolight` package holds every public VTK class of the Mesolight modules.

    python TestPackage.py CLASS...   (the classes: one per installed header with a vtkTypeMacro,
                                      listed by CMake from the module sources)

Each class must be importable from the package, be a vtkObjectBase, and (unless abstract) make
an instance that knows its class name; nothing that is not a Mesolight class (VTK's own, private
classes) may be re-exported.
"""
import sys

from vtkmodules.vtkCommonCore import vtkObjectBase

import mesolight


def main(expected):
    failures = []
    exported = set(mesolight.__all__)
    for name in expected:
        cls = getattr(mesolight, name, None)
        if cls is None or name not in exported:
            failures.append(f"{name}: not in the mesolight package")
            continue
        if not issubclass(cls, vtkObjectBase):
            failures.append(f"{name}: not a VTK class")
            continue
        try:
            instance = cls()
        except TypeError:  # abstract: no New()
            print(f"{name}: abstract")
            continue
        if instance.GetClassName() != name:
            failures.append(f"{name}: instance says it is a {instance.GetClassName()}")
    extra = sorted(exported - set(expected))
    if extra:
        failures.append(f"exported but not public Mesolight classes: {', '.join(extra)}")
    for failure in failures:
        print(failure)
    print(f"{len(expected)} classes expected, {len(exported)} exported, "
          f"{len(failures)} problems")
    return 1 if failures or not expected else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
