"""GUI test: runs inside the real ParaView client (paraview --script=...), the plugin auto-loaded from
PV_PLUGIN_PATH as an installed plugin is. It applies Mesh Signed Distance to Data/trefoil.obj and shows
the zero contour and a slice coloured by distance; ParaView's test utility then compares the view with
Testing/Baseline/GuiMeshSignedDistance.png (see Testing/CMakeLists.txt). A Python error leaves the
view empty, so the comparison fails.
"""
import os
import traceback

from paraview.simple import *  # noqa: F401,F403

try:
    layout = GetLayout()
    layout.SetSize(600, 400)
    view = GetActiveView()
    view.OrientationAxesVisibility = 0
    reader = OpenDataFile(os.environ["SHRINKWRAP_MESH"])
    sdf = MeshSignedDistance(Input=reader, Resolution=80)
    surface = Contour(Input=sdf, ContourBy=["POINTS", "SignedDistance"], Isosurfaces=[0.0])
    shown = Show(surface, view)
    ColorBy(shown, None)
    shown.DiffuseColor = [0.85, 0.85, 0.8]
    cut = Slice(Input=sdf)
    cut.SliceType.Normal = [0.0, 0.0, 1.0]
    sliced = Show(cut, view)
    ColorBy(sliced, ("POINTS", "SignedDistance"))
    lut = GetColorTransferFunction("SignedDistance")
    lut.ApplyPreset("Cool to Warm", True)
    lut.RescaleTransferFunction(-2.0, 2.0)
    Hide3DWidgets(proxy=cut.SliceType)
    view.CameraPosition = [6.0, -9.0, 9.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    b = reader.GetDataInformation().GetBounds()
    view.ResetCamera(b[0], b[1], b[2], b[3], b[4], b[5])
    Render(view)
except Exception:
    traceback.print_exc()
