# SPDX-License-Identifier: BSD-3-Clause
"""Checks called from the XML GUI tests (run-gui-test.sh T.xml: `paraview --test-script=T.xml
--exit`), whose events click the real Apply button (pqApplyBehavior) and create proxies from the
menus (pqObjectBuilder, so each first Apply is the GUI's own). The XML runs these functions
through the Python Shell (`executeCommand`); each check is printed and kept, and finish()
writes "OK" or the failures to $MESOLIGHT_GUI_RESULT, as mesolight_guitest.run does. A check
the XML never reaches (a widget not found, a dialog that did not open) leaves no "OK": the
wrapper reports the failure."""
import functools
import sys
import traceback

import mesolight_guitest as g
import numpy as np
import paraview.simple as pvs

_failures = []


def _print(text):
    # The Python Shell shows print(); the process' own stdout reaches ctest's log.
    sys.__stdout__.write(text + "\n")
    sys.__stdout__.flush()


def _check(ok, text):
    _print("%s: %s" % ("ok" if ok else "FAILED", text))
    if not ok:
        _failures.append(text)


def _guarded(check):
    """An exception in a check is a failure (the Python Shell would only print it)."""
    @functools.wraps(check)
    def wrapper(*args):
        try:
            check(*args)
        except Exception:
            _check(False, "%s raised:\n%s" % (check.__name__, traceback.format_exc()))
    return wrapper


def source(xml_name):
    """The one pipeline source of that proxy type (created from the menus)."""
    found = [s for s in pvs.GetSources().values() if s.GetXMLName() == xml_name]
    if len(found) != 1:
        raise RuntimeError("%d sources of type %s" % (len(found), xml_name))
    return found[0]


@_guarded
def interaction_mode(expected, when):
    mode = g.gui_view().InteractionMode
    _check(mode == expected, "interaction mode %s %s (expected %s)" % (mode, when, expected))


@_guarded
def relief_shown_framed(min_span=0.5):
    """After the README pipeline's last Apply: Relief Surface, the only visible data, framed:
    the relief's box on screen spans at least min_span of the view's smaller side (the view's
    shape depends on the docks the test opened; a dot spans a few pixels)."""
    view = g.gui_view()
    attached = source("MesolightAttachReliefTexture")
    display = pvs.GetDisplayProperties(attached, view)
    _check(display.Representation == "Relief Surface",
           "Attach Relief Texture shown as %r" % display.Representation)
    visible = [r.Input.GetXMLName() for r in g.visible_data_representations(view)]
    _check(visible == ["MesolightAttachReliefTexture"], "visible data: %s" % visible)
    frame = g.grab(view, "gui-apply-relief.png")
    display.Visibility = 0
    empty = g.grab(view, "gui-apply-relief-background.png")
    display.Visibility = 1
    pvs.Render(view)
    mask = g.covered(frame, empty)
    rows = np.flatnonzero(mask.any(axis=1))
    cols = np.flatnonzero(mask.any(axis=0))
    extent = max(rows[-1] - rows[0] + 1, cols[-1] - cols[0] + 1) if rows.size else 0
    span = extent / float(min(mask.shape))
    _check(span >= min_span,
           "the relief spans %.3f of the view's smaller side (%d of %d x %d pixels; at least "
           "%.2f: framed, not a dot); it covers %.3f of the view"
           % (span, extent, mask.shape[1], mask.shape[0], min_span, float(mask.mean())))


@_guarded
def light_set_input(expected):
    """Attach Relief Texture's Light Set input: the proxy type of its producer, or None."""
    prop = source("MesolightAttachReliefTexture").LightSet
    name = getattr(prop, "Proxy", prop).GetXMLName() if prop is not None else None
    _check(name == expected, "Light Set input %s (expected %s)" % (name, expected))


@_guarded
def light_set_attached(expected):
    display = pvs.GetDisplayProperties(source("MesolightAttachReliefTexture"), g.gui_view())
    value = display.LightSetAttached
    _check(value == expected, "LightSetAttached %d (expected %d)" % (value, expected))


@_guarded
def delete_negative_case():
    """Deletes the first part's Plane and Linear Extrusion: the README pipeline starts anew."""
    for name in ("LinearExtrusionFilter", "PlaneSource"):
        pvs.Delete(source(name))
    pvs.Render(g.gui_view())


def finish():
    verdict = "OK\n" if not _failures else "FAILED\n" + "\n".join(_failures) + "\n"
    _print(verdict)
    if g.RESULT:
        with open(g.RESULT, "w") as f:
            f.write(verdict)


@_guarded
def select_attach():
    """Makes Attach Relief Texture the active source (what clicking it in the Pipeline Browser
    does), so Edit > Change Input and the panel are its."""
    pvs.SetActiveSource(source("MesolightAttachReliefTexture"))
