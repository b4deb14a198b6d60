"""pvpython test of Shrink Wrap following a time series (Time Mode), as a user opens one: a .pvd of
four torus frames at times 0, 10, 20 and 30, moving along x by 0.2 a frame.

Usage: pvpython TestFollowTime.py <ShrinkWrap plugin .so> <unused mesh>
"""
import math
import os
import shutil
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from checks import check, finish

plugin = sys.argv[1]
folder = tempfile.mkdtemp(prefix="shrinkwrap_series_")
times = [0, 10, 20, 30]
shift = 0.2
entries = []
for k, t in enumerate(times):
    torus = vtkParametricTorus()
    torus.SetRingRadius(1.0)
    torus.SetCrossSectionRadius(0.4)
    source = vtkParametricFunctionSource()
    source.SetParametricFunction(torus)
    source.SetUResolution(60)
    source.SetVResolution(30)
    closed = vtkCleanPolyData()  # the parametric seam's points merged: a closed torus
    closed.ToleranceIsAbsoluteOn()
    closed.SetAbsoluteTolerance(1e-6)
    closed.SetInputConnection(source.GetOutputPort())
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(closed.GetOutputPort())
    move = vtkTransform()
    move.Translate(shift * k, 0, 0)
    moved = vtkTransformPolyDataFilter()
    moved.SetInputConnection(triangles.GetOutputPort())
    moved.SetTransform(move)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(moved.GetOutputPort())
    name = "torus_%d.vtp" % k
    writer.SetFileName(os.path.join(folder, name))
    writer.SetDataModeToAscii()
    writer.Write()
    del writer
    entries.append('    <DataSet timestep="%g" file="%s"/>' % (t, name))
series = os.path.join(folder, "torus.pvd")
with open(series, "w") as pvd:
    pvd.write('<VTKFile type="Collection" version="0.1">\n  <Collection>\n%s\n  </Collection>\n'
              "</VTKFile>\n" % "\n".join(entries))

LoadPlugin(plugin, ns=globals())
reader = OpenDataFile(series)
wrap = ShrinkWrap(Input=reader)
check(list(wrap.TimestepValues) == times, "the wrap's times are the series' (%s)" % list(wrap.TimestepValues))
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
check(scene.EndTime == 30, "the animation ends at the series' last time")


def at(t):
    wrap.UpdatePipeline(t)
    return servermanager.Fetch(wrap)


def field(data, name):
    return data.GetFieldData().GetAbstractArray(name).GetValue(0)


frames = {t: at(t) for t in times}
for t in times:
    data = frames[t]
    check(data.GetNumberOfPoints() > 100 and field(data, "Time") == t,
          "frame %g wrapped (%d vertices, Time %g, %s)" % (t, data.GetNumberOfPoints(), field(data, "Time"),
                                                            field(data, "Status")))
# The wrap moves with the torus: its x range shifts by 0.2 a frame.
xs = [frames[t].GetBounds()[0] for t in times]
check(all(abs((xs[k] - xs[0]) - shift * k) < 0.01 for k in range(4)),
      "the wrap follows the torus along x (%s)" % ["%.3f" % x for x in xs])
last = frames[30]
displacement = last.GetPointData().GetArray("Displacement")
velocity = last.GetPointData().GetArray("Velocity")
check(displacement is not None and velocity is not None and last.GetPointData().GetArray("TrackId") is not None,
      "TrackId, Displacement and Velocity on the wrap")
worst = max(math.dist(displacement.GetTuple3(i), (shift, 0, 0)) for i in range(last.GetNumberOfPoints()))
check(worst < 0.01, "Displacement = the translation at every vertex (worst off by %.2g)" % worst)
worst = max(math.dist(velocity.GetTuple3(i), (shift / 10, 0, 0)) for i in range(last.GetNumberOfPoints()))
check(worst < 0.001, "Velocity = the translation over the 10 time units (worst off by %.2g)" % worst)
check(field(at(25), "Time") == 20, "a time between frames gives the frame before it")
Delete(wrap)
Delete(reader)
shutil.rmtree(folder)
finish()
