"""Time series for the pvpython and GUI tests: a closed torus, and a .pvd of frames written as
ParaView reads them."""
import os

from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def torus(cross_section, u_resolution, v_resolution):
    """A closed triangulated torus of ring radius 1 about the z axis."""
    shape = vtkParametricTorus()
    shape.SetRingRadius(1.0)
    shape.SetCrossSectionRadius(cross_section)
    source = vtkParametricFunctionSource()
    source.SetParametricFunction(shape)
    source.SetUResolution(u_resolution)
    source.SetVResolution(v_resolution)
    closed = vtkCleanPolyData()  # the parametric seam's points merged, its triangles kept as such
    closed.ConvertPolysToLinesOff()
    closed.ConvertLinesToPointsOff()
    closed.ToleranceIsAbsoluteOn()
    closed.SetAbsoluteTolerance(1e-6)
    closed.SetInputConnection(source.GetOutputPort())
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(closed.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


def write_series(folder, name, mesh, times, move):
    """Frames of `mesh` at `times`, frame k with every point p at move(p, k), as <name>_KK.vtp files
    and <name>.pvd in `folder`; returns the .pvd's path. ASCII: raw appended data does not read back
    under newer Expat (VTK issue 19258)."""
    entries = []
    for k, t in enumerate(times):
        frame = mesh.NewInstance()
        frame.DeepCopy(mesh)
        points = vtkPoints()
        for i in range(mesh.GetNumberOfPoints()):
            points.InsertNextPoint(move(mesh.GetPoint(i), k))
        frame.SetPoints(points)
        writer = vtkXMLPolyDataWriter()
        writer.SetInputData(frame)
        writer.SetDataModeToAscii()
        file_name = "%s_%02d.vtp" % (name, k)
        writer.SetFileName(os.path.join(folder, file_name))
        writer.Write()
        entries.append('    <DataSet timestep="%g" file="%s"/>' % (t, file_name))
    series = os.path.join(folder, name + ".pvd")
    with open(series, "w") as pvd:
        pvd.write('<VTKFile type="Collection" version="0.1">\n  <Collection>\n%s\n  </Collection>\n'
                  "</VTKFile>\n" % "\n".join(entries))
    return series
