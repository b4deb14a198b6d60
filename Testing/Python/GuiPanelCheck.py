"""Run in the GUI's Python shell after the panel events of GuiPanel.xml.in: writes what the panel did
(PanelWrap's Distance Field, and whether its wrap equals the one connected as Change Input connects
it) to $SHRINKWRAP_PANEL/result.txt, and the Properties panel as the screen shows it to panel.png
(ImageMagick's import; the window is 1280 x 1024 at the screen's corner)."""
import os
import subprocess

import numpy as np
from paraview.simple import FindSource, GetSources
from vtkmodules.util.numpy_support import vtk_to_numpy

out = os.environ["SHRINKWRAP_PANEL"]
os.makedirs(out, exist_ok=True)
panel_wrap, changed = FindSource("PanelWrap"), FindSource("ChangedInput")
connected = panel_wrap.DistanceField
name = "none" if connected is None else [k for k, v in GetSources().items() if v == connected][0][0]



def last_step(proxy):
    """The wrap at its last time step (the GUI shows time 0), from the built-in server."""
    proxy.UpdatePipeline(proxy.TimestepValues[-1])
    return proxy.GetClientSideObject().GetOutputDataObject(0)


a, b = last_step(panel_wrap), last_step(changed)
equal = (a.GetNumberOfPoints() > 0 and a.GetNumberOfPoints() == b.GetNumberOfPoints() and
         np.array_equal(vtk_to_numpy(a.GetPoints().GetData()), vtk_to_numpy(b.GetPoints().GetData())))
differing = [p for p in panel_wrap.ListProperties() if p not in ("DistanceField",) and
             str(panel_wrap.GetPropertyValue(p)) != str(changed.GetPropertyValue(p))]
with open(os.path.join(out, "result.txt"), "w") as f:
    f.write("PanelWrap Distance Field: %s\nwrap equals Change Input's: %s\nvertices: %d and %d\n"
            "properties that differ: %s\n" % (name, equal, a.GetNumberOfPoints(), b.GetNumberOfPoints(),
                                                 differing or "none"))
subprocess.run(["import", "-window", "root", "-crop", "292x540+0+478", "+repage",
                os.path.join(out, "panel.png")], check=True)
