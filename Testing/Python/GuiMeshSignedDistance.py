"""GUI test: runs inside the real ParaView client (paraview --script=...), the plugin auto-loaded from
PV_PLUGIN_PATH as an installed plugin is. It applies Mesh Signed Distance to Data/trefoil.obj and shows
the demo's picture (Examples/demo.py); ParaView's test utility then compares the view with
Testing/Baseline/GuiMeshSignedDistance.png (see Testing/CMakeLists.txt). A Python error leaves the
view empty, so the comparison fails.
"""
import os
import sys
import traceback

from paraview.simple import *  # noqa: F401,F403

try:
    sys.path.insert(0, os.environ["SHRINKWRAP_EXAMPLES"])
    from demo import show_distance_field

    GetLayout().SetSize(600, 400)
    reader = OpenDataFile(os.environ["SHRINKWRAP_MESH"])
    sdf = MeshSignedDistance(Input=reader, Resolution=80)
    view = GetActiveView()
    show_distance_field(reader, sdf, view)
    Render(view)
except Exception:
    traceback.print_exc()
