"""pvpython test of Shrink Wrap following a time series (Time Mode), as a user opens one: a .pvd of
four torus frames at times 0, 10, 20 and 30, moving along x by 0.2 a frame.

Usage: pvpython TestFollowTime.py <ShrinkWrap plugin .so> <unused mesh>
"""
import math
import shutil
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

from checks import check, finish
from series import torus, write_series

plugin = sys.argv[1]
folder = tempfile.mkdtemp(prefix="shrinkwrap_series_")
times = [0, 10, 20, 30]
shift = 0.2
series = write_series(folder, "torus", torus(0.4, 60, 30), times,
                      lambda p, k: (p[0] + shift * k, p[1], p[2]))

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
