"""Run in the GUI's Python shell by the events of GuiPanel.xml.in, with `part` set:
- "panel", after the panel events: writes what the panel did (PanelWrap's Distance Field, and whether
  its wrap equals the one connected as Change Input connects it) to $SHRINKWRAP_PANEL/result.txt, and
  the Properties panel as the screen shows it to panel.png (ImageMagick's import; the window is
  1280 x 1024 at the screen's corner); then selects the mesh and the field together;
- "selection", after Shrink Wrap was created from the menu with both selected: appends what the new
  filter's Input and Distance Field hold and whether its wrap equals Change Input's."""
import os
import subprocess

import numpy as np
from paraview.modules.vtkRemotingServerManager import vtkSMProxyManager, vtkSMProxySelectionModel
from paraview.simple import FindSource, GetSources
from vtkmodules.util.numpy_support import vtk_to_numpy

out = os.environ["SHRINKWRAP_PANEL"]
part = globals().get("part", "panel")
os.makedirs(out, exist_ok=True)


def last_step(proxy):
    """The wrap at its last time step (the GUI shows time 0), from the built-in server."""
    proxy.UpdatePipeline(proxy.TimestepValues[-1])
    return proxy.GetClientSideObject().GetOutputDataObject(0)


def same_wrap(a, b):
    return (a.GetNumberOfPoints() > 0 and a.GetNumberOfPoints() == b.GetNumberOfPoints() and
            np.array_equal(vtk_to_numpy(a.GetPoints().GetData()), vtk_to_numpy(b.GetPoints().GetData())))


def name_of(proxy):
    return "none" if proxy is None else [k for k, v in GetSources().items() if v == proxy][0][0]


changed = FindSource("ChangedInput")
reference = last_step(changed)
if part == "panel":
    panel_wrap = FindSource("PanelWrap")
    a = last_step(panel_wrap)
    differing = [p for p in panel_wrap.ListProperties() if p not in ("DistanceField",) and
                 str(panel_wrap.GetPropertyValue(p)) != str(changed.GetPropertyValue(p))]
    with open(os.path.join(out, "result.txt"), "w") as f:
        f.write("PanelWrap Distance Field: %s\nwrap equals Change Input's: %s\nvertices: %d and %d\n"
                "properties that differ: %s\n" % (name_of(panel_wrap.DistanceField), same_wrap(a, reference),
                                                     a.GetNumberOfPoints(), reference.GetNumberOfPoints(),
                                                     differing or "none"))
    subprocess.run(["import", "-window", "root", "-crop", "292x540+0+478", "+repage",
                    os.path.join(out, "panel.png")], check=True)
    model = vtkSMProxyManager.GetProxyManager().GetActiveSessionProxyManager().GetSelectionModel("ActiveSources")
    model.Select(FindSource("Mesh").SMProxy, vtkSMProxySelectionModel.CLEAR_AND_SELECT)
    model.Select(FindSource("Field").SMProxy, vtkSMProxySelectionModel.SELECT)
else:
    created = FindSource("ShrinkWrap1")
    inputs = [] if created is None else sorted(name_of(p) for p in created.Input)
    made = last_step(created) if created is not None else None
    same = made is not None and same_wrap(made, reference)
    with open(os.path.join(out, "result.txt"), "a") as f:
        f.write("created from the menu with Mesh and Field selected, Input: %s, Distance Field: %s\n"
                "its wrap equals Change Input's: %s\nvertices: %d and %d\n"
                % (", ".join(inputs), name_of(created.DistanceField) if created else "none", same, made.GetNumberOfPoints() if made else 0,
                   reference.GetNumberOfPoints()))
