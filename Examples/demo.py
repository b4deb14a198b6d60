"""The main job on the default data: the signed distance field of a mesh, and the mesh shrink-wrapped.

Usage: pvbatch Examples/demo.py <ShrinkWrap plugin .so> [mesh] [output folder]
Writes, in the output folder: <name>_sdf.vti and <name>_sdf.png (the zero contour, and a slice coloured
by signed distance with isolines); <name>_wrap.vtp (the final wrap), <name>_wrap.pvd with about 25
steps in <name>_wrap/ (every step at the default 25), and <name>_wrap.png (the wrap over the target); and prints a short report.
"""
import os
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from paraview.vtk.vtkFiltersCore import vtkExtractEdges


def save(path, proxy):
    """Writes proxy's data to a VTK XML file with the data inline (base64), then reads it back. ParaView's
    default, raw appended data, is not read back where Expat defers reparsing (2.6.0 on, and Debian 12's
    security updates of 2.5.0: VTK issue 19258): a file ParaView cannot open would be no output."""
    SaveData(path, proxy=proxy, DataMode="Binary")
    written = OpenDataFile(path)
    written.UpdatePipeline()
    points = written.GetDataInformation().GetNumberOfPoints()
    Delete(written)
    if points != proxy.GetDataInformation().GetNumberOfPoints():
        sys.exit("%s was written but reads back with %d points, not %d" % (
            path, points, proxy.GetDataInformation().GetNumberOfPoints()))


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


def show_wrap(reader, wrap, view, h):
    """The picture of a wrap: the target in grey under the wrap's edges, coloured by distance (+-2 h)."""
    view.OrientationAxesVisibility = 0
    target = Show(reader, view)
    target.ColorArrayName = ["POINTS", ""]
    target.DiffuseColor = [0.75, 0.75, 0.7]
    shown = Show(wrap, view)
    ColorBy(shown, ("POINTS", "Distance"))
    shown.SetRepresentationType("Surface With Edges")
    shown.Opacity = 0.55
    lut = GetColorTransferFunction("Distance")
    lut.ApplyPreset("Cool to Warm", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(-2 * h, 2 * h)
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "distance to target", ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    shown.SetScalarBarVisibility(view, True)


def shrink_wrap(reader, sdf, out, name, h):
    """Shrink Wrap with its defaults on the field just computed (its box holds the offset start);
    files, picture and report."""
    wrap = ShrinkWrap(Input=reader, DistanceField=sdf)
    tau, steps = wrap.TimePerStep, wrap.NumberOfSteps
    start = time.time()
    wrap.UpdatePipeline(steps * tau)
    seconds = time.time() - start
    final = servermanager.Fetch(wrap)
    save(os.path.join(out, name + "_wrap.vtp"), wrap)

    # A series of about 25 steps (every step at the default 25), for ParaView's animation.
    folder = os.path.join(out, name + "_wrap")
    os.makedirs(folder, exist_ok=True)
    entries = []
    for k in range(0, steps + 1, max(1, steps // 25)):
        wrap.UpdatePipeline(k * tau)
        file = "step_%04d.vtp" % k
        save(os.path.join(folder, file), wrap)
        entries.append('    <DataSet timestep="%g" file="%s/%s"/>' % (k * tau, name + "_wrap", file))
    with open(os.path.join(out, name + "_wrap.pvd"), "w") as pvd:
        pvd.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n')
        pvd.write("\n".join(entries) + "\n  </Collection>\n</VTKFile>\n")

    # The wrap over the target.
    view = CreateView("RenderView")
    view.ViewSize = [1200, 800]
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    view.ViewTime = steps * tau  # the view shows its own time: the last step
    show_wrap(reader, wrap, view, h)
    view.CameraPosition = [6.0, -9.0, 9.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera(*reader.GetDataInformation().GetBounds())
    view.GetActiveCamera().Dolly(1.5)  # the reset frames the bounding sphere: closer, the wrap fills the picture
    png = os.path.join(out, name + "_wrap.png")
    SaveScreenshot(png, view, ImageResolution=[1200, 800])

    distance = sorted(abs(final.GetPointData().GetArray("Distance").GetValue(i)) for i in range(final.GetNumberOfPoints()))
    angles = final.GetCellData().GetArray("MinAngle")
    small = sum(1 for i in range(angles.GetNumberOfTuples()) if angles.GetValue(i) < 20.0)
    status = final.GetFieldData().GetAbstractArray("Status").GetValue(0)
    edges = vtkExtractEdges()
    edges.SetInputData(final)
    edges.Update()
    euler = final.GetNumberOfPoints() - edges.GetOutput().GetNumberOfLines() + final.GetNumberOfPolys()
    return "\n".join([
        "Shrink Wrap of %s: %d steps of %g, %d vertices, %.2f s, status %s" % (
            name, steps, tau, final.GetNumberOfPoints(), seconds, status),
        "  closeness |d|: median %.2f h, 90th percentile %.2f h (h = %.4g, the field's cell)" % (
            distance[len(distance) // 2] / h, distance[len(distance) * 9 // 10] / h, h),
        "  triangles with a minimum angle below 20 degrees: %.1f%%" % (100.0 * small / angles.GetNumberOfTuples()),
        "  genus %d (Euler characteristic %d), %d self-intersecting triangle pairs" % (
            (2 - euler) // 2, euler, final.GetFieldData().GetArray("SelfIntersections").GetValue(0)),
        "  wrote %s_wrap.vtp, %s_wrap.pvd (about 25 steps) and %s" % (name, name, png)])


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
    save(vti, sdf)

    view = CreateView("RenderView")
    view.ViewSize = [1200, 800]
    view.Background = [1, 1, 1]
    view.UseColorPaletteForBackground = 0
    show_distance_field(reader, sdf, view)
    png = os.path.join(out, name + "_sdf.png")
    SaveScreenshot(png, view, ImageResolution=[1200, 800])

    wrap_report = shrink_wrap(reader, sdf, out, name, image.GetSpacing()[0])

    low, high = image.GetPointData().GetArray("SignedDistance").GetRange()
    status = image.GetFieldData().GetAbstractArray("DistanceStatus").GetValue(0)
    print("Mesh Signed Distance of %s" % mesh)
    print("  grid %d x %d x %d nodes, cell size %.4g, %.2f s" % (image.GetDimensions() + (image.GetSpacing()[0], seconds)))
    print("  distance range [%.4g, %.4g], %s" % (low, high, status))
    print("  wrote %s and %s" % (vti, png))
    print(wrap_report)


if __name__ == "__main__":
    main()
