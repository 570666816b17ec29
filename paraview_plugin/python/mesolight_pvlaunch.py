# SPDX-License-Identifier: BSD-3-Clause
"""Start-up of scripts/pvpython.sh and scripts/pvbatch.sh, run by pvpython / pvbatch before the
user's script (or the interactive prompt, pvpython -i):

1. ParaView's own Python modules first on sys.path. pvpython (not pvbatch) puts
   /lib/python3/dist-packages in front of PYTHONPATH, found by the landmark vtkmodules/__init__.py
   beside its libraries; with python3-vtk9 (VTK 9.1, which the main build needs) installed there
   instead of python3-paraview, `import paraview.simple` loads VTK 9.1's vtkmodules into
   ParaView's VTK 9.2 and dies with SIGSEGV. The unpacked python3-paraview copy goes first; the
   system directory stays (NumPy lives there).
2. LoadPlugin of a plugin that is already loaded does nothing. The launchers auto-load the
   plugin (PV_PLUGIN_PATH); ParaView 5.11's vtkPVPluginLoader returns early for a file it has
   loaded without setting its Loaded flag, so in pvbatch (which loads local plugins through the
   PluginLoader proxy) LoadPlugin of the same file printed "Plugin load failed: No plugin loaded
   yet." though the plugin was there and the call succeeded.
3. Runs the script given as the first argument as __main__ with the remaining arguments.
"""
import os
import sys


def _paraview_first():
    wanted = os.environ.get("MESOLIGHT_PARAVIEW_PYTHON", "")
    if not wanted:
        return
    real = os.path.realpath(wanted)
    sys.path[:] = [wanted] + [p for p in sys.path if os.path.realpath(p or ".") != real]


def _load_plugin_once():
    from paraview import servermanager
    from paraview.modules.vtkRemotingCore import vtkPVPluginTracker

    load = servermanager.LoadPlugin

    def LoadPlugin(filename, remote=True, connection=None):
        tracker = vtkPVPluginTracker.GetInstance()
        wanted = os.path.realpath(filename)
        for i in range(tracker.GetNumberOfPlugins()):
            loaded = tracker.GetPluginFileName(i)
            if loaded and tracker.GetPluginLoaded(i) and os.path.realpath(loaded) == wanted:
                return  # auto-loaded by the launcher: nothing to do
        return load(filename, remote, connection)

    LoadPlugin.__doc__ = load.__doc__
    servermanager.LoadPlugin = LoadPlugin


_paraview_first()
_load_plugin_once()
if len(sys.argv) > 1:
    import runpy

    sys.argv = sys.argv[1:]
    runpy.run_path(sys.argv[0], run_name="__main__")
