"""Renders a target mesh (or point cloud), its Shrink Wrap at the defaults and CGAL's alpha wrap
(diag/50) side by side, edges shown, as the benchmark writes them (<name>_target.vtp, <name>_shrinkwrap.vtp,
<name>_alphawrap_50.vtp).
Usage: Testing/run-with-x.sh pvbatch render_wraps.py <folder> <name> <out.png> [view direction x,y,z] [view up x,y,z]"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

folder, name, png = sys.argv[1], sys.argv[2], sys.argv[3]
direction = [float(v) for v in sys.argv[4].split(",")] if len(sys.argv) > 4 else [0.0, 0.0, 1.0]
up = [float(v) for v in sys.argv[5].split(",")] if len(sys.argv) > 5 else [0.0, 1.0, 0.0]
panels = [(name + "_target.vtp", name + " (target)"),
          (name + "_shrinkwrap.vtp", "Shrink Wrap, defaults"),
          (name + "_alphawrap_50.vtp", "CGAL alpha_wrap_3, alpha = diag/50")]
panels = [p for p in panels if os.path.exists(os.path.join(folder, p[0]))]
if not panels:
    sys.exit("render_wraps.py: no %s_*.vtp in %s" % (name, folder))
layout = CreateLayout("wraps")
cells = [0]
for i in range(1, len(panels)):  # split the last cell: 1/n to the left, the rest to the right
    layout.SplitHorizontal(cells[-1], 1.0 / (len(panels) - i + 1))
    cells[-1:] = [2 * cells[-1] + 1, 2 * cells[-1] + 2]
for i, (file, title) in enumerate(panels):
    view = CreateView("RenderView")
    layout.AssignView(cells[i], view)
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    reader = XMLPolyDataReader(FileName=[os.path.join(folder, file)])
    reader.UpdatePipeline()
    shown = Show(reader, view)
    if reader.GetDataInformation().GetNumberOfCells() == reader.GetDataInformation().GetNumberOfPoints():
        # a point cloud (BenchShrinkWrap --points): its vertices
        shown.SetRepresentationType("Points")
        shown.PointSize = 2
        title = "%s, %d points" % (name.replace("_points", ""), reader.GetDataInformation().GetNumberOfPoints())
    else:
        shown.SetRepresentationType("Surface With Edges")
    shown.AmbientColor = shown.DiffuseColor = [0.85, 0.85, 0.8]
    shown.EdgeColor = [0.2, 0.2, 0.5]
    label = Show(Text(Text=title), view)
    label.Color = [0.1, 0.1, 0.1]
    label.FontSize = 14
    view.CameraPosition = direction
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = up
    ResetCamera(view)
width = 600 * len(panels)
layout.SetSize(width, 650)
SaveScreenshot(png, layout, ImageResolution=[width, 650])
print("wrote", png)
