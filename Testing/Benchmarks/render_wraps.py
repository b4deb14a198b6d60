"""Renders Shrink Wrap (s = 4, with D = 0 and, when written, D = 0.5; from the offset surface with D = 0.5) and CGAL's
alpha wrap (diag/50) of a mesh side by side, edges shown.
Usage: Testing/run-with-x.sh pvbatch render_wraps.py <folder with the benchmark's .vtp files> <name> <out.png>"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403

folder, name, png = sys.argv[1], sys.argv[2], sys.argv[3]
panels = [(name + "_shrinkwrap_s4.vtp", "Shrink Wrap, s = 4 (2562 vertices), D = 0"),
          (name + "_shrinkwrap_s4_D05.vtp", "Shrink Wrap, s = 4, D = 0.5"),
          (name + "_shrinkwrap_offset_D05.vtp", "Shrink Wrap, offset start, D = 0.5"),
          (name + "_alphawrap_50.vtp", "CGAL alpha_wrap_3, alpha = diag/50")]
panels = [p for p in panels if os.path.exists(os.path.join(folder, p[0]))]
layout = CreateLayout("wraps")
cells = [0]
for i in range(1, len(panels)):  # split the last cell: 1/n to the left, the rest to the right
    layout.SplitHorizontal(cells[-1], 1.0 / (len(panels) - i + 1))
    cells[-1:] = [2 * cells[-1] + 1, 2 * cells[-1] + 2]
views = []
for i, (file, title) in enumerate(panels):
    view = CreateView("RenderView")
    layout.AssignView(cells[i], view)
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    shown = Show(XMLPolyDataReader(FileName=[os.path.join(folder, file)]), view)
    shown.SetRepresentationType("Surface With Edges")
    shown.AmbientColor = shown.DiffuseColor = [0.85, 0.85, 0.8]
    shown.EdgeColor = [0.2, 0.2, 0.5]
    text = Text(Text=title)
    label = Show(text, view)
    label.Color = [0.1, 0.1, 0.1]
    label.FontSize = 14
    view.CameraPosition = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    ResetCamera(view)
    views.append(view)
width = 600 * len(panels)
layout.SetSize(width, 650)
SaveScreenshot(png, layout, ImageResolution=[width, 650])
print("wrote", png)
