"""The main job on the default data: the signed distance field of a mesh, saved and pictured.

Usage: pvbatch Examples/demo.py <ShrinkWrap plugin .so> [mesh] [output folder]
Writes <output>/<name>_sdf.vti and <output>/<name>_sdf.png (the zero contour, and a slice coloured by
signed distance with isolines) and prints a short report.
"""
import os
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager


def show_distance_field(reader, sdf, view):
    """The picture of a signed distance field: its zero contour and a z slice coloured by distance."""
    surface = Contour(Input=sdf, ContourBy=["POINTS", "SignedDistance"], Isosurfaces=[0.0])
    shown = Show(surface, view)
    ColorBy(shown, None)
    shown.DiffuseColor = [0.85, 0.85, 0.8]
    cut = Slice(Input=sdf)
    cut.SliceType.Normal = [0.0, 0.0, 1.0]
    Hide3DWidgets(proxy=cut.SliceType)
    sliced = Show(cut, view)
    ColorBy(sliced, ("POINTS", "SignedDistance"))
    bounds = reader.GetDataInformation().GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    lut = GetColorTransferFunction("SignedDistance")
    lut.ApplyPreset("Cool to Warm", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(-0.25 * size, 0.25 * size)
    isolines = Contour(Input=cut, ContourBy=["POINTS", "SignedDistance"],
                       Isosurfaces=[k * 0.05 * size for k in range(-5, 11)])
    lines = Show(isolines, view)
    ColorBy(lines, None)
    lines.AmbientColor = lines.DiffuseColor = [0.2, 0.2, 0.2]
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "signed distance", ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    sliced.SetScalarBarVisibility(view, True)
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [6.0, -9.0, 9.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera(*bounds)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    plugin = sys.argv[1]
    mesh = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "Data", "trefoil.obj")
    out = sys.argv[3] if len(sys.argv) > 3 else "out"
    os.makedirs(out, exist_ok=True)
    name = os.path.splitext(os.path.basename(mesh))[0]

    LoadPlugin(plugin, ns=globals())
    reader = OpenDataFile(mesh)
    sdf = MeshSignedDistance(Input=reader, Resolution=120)
    start = time.time()
    sdf.UpdatePipeline()
    seconds = time.time() - start
    image = servermanager.Fetch(sdf)
    if image.GetNumberOfPoints() == 0:
        sys.exit("Mesh Signed Distance produced no output (see the errors above)")
    vti = os.path.join(out, name + "_sdf.vti")
    SaveData(vti, proxy=sdf)

    view = CreateView("RenderView")
    view.ViewSize = [1200, 800]
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    show_distance_field(reader, sdf, view)
    png = os.path.join(out, name + "_sdf.png")
    SaveScreenshot(png, view, ImageResolution=[1200, 800])

    low, high = image.GetPointData().GetArray("SignedDistance").GetRange()
    status = image.GetFieldData().GetAbstractArray("DistanceStatus").GetValue(0)
    print("Mesh Signed Distance of %s" % mesh)
    print("  grid %d x %d x %d nodes, cell size %.4g, %.2f s" % (image.GetDimensions() + (image.GetSpacing()[0], seconds)))
    print("  distance range [%.4g, %.4g], %s" % (low, high, status))
    print("  wrote %s and %s" % (vti, png))


if __name__ == "__main__":
    main()
