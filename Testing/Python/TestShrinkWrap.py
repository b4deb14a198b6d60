"""pvpython test of Shrink Wrap's time awareness, as the ParaView animation uses it.

Usage: pvpython TestShrinkWrap.py <ShrinkWrap plugin .so> <mesh>
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

from checks import abort_at, check, finish

plugin, mesh = sys.argv[1], sys.argv[2]



def computed(proxy):
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty("NumberOfComputedSteps").GetData()


def points(proxy):
    data = servermanager.Fetch(proxy)
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())], data


LoadPlugin(plugin, ns=globals())
reader = OpenDataFile(mesh)
wrap = ShrinkWrap(Input=reader, NumberOfSteps=40, Resolution=64)
tau = wrap.TimePerStep
check(len(wrap.TimestepValues) == 41, "TimestepValues has N_t + 1 = 41 entries")
check(abs(wrap.TimestepValues[-1] - 40 * tau) < 1e-12, "the last time is N_t tau")

# The animation scene picks the steps up.
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
check(abs(scene.EndTime - 40 * tau) < 1e-12, "the animation ends at the last step")

wrap.UpdatePipeline(40 * tau)
check(computed(wrap) == 40, "the last step computes 40 steps")
wrap.UpdatePipeline(20 * tau)
middle, data = points(wrap)
check(data.GetFieldData().GetArray("StepIndex").GetValue(0) == 20, "UpdatePipeline(20 tau) gives step 20")
check(computed(wrap) == 40, "going back after going forward computes nothing")

fresh = ShrinkWrap(Input=reader, NumberOfSteps=20, Resolution=64)
fresh.UpdatePipeline()
check(points(fresh)[0] == middle, "the same points as a fresh run stopped at step 20")

wrap.AdvectionSpeed = 2.0
wrap.UpdatePipeline(5 * tau)
check(computed(wrap) == 5, "changing C drops the cache (5 steps computed again)")

# During a long run: progress per step; a property edited while it runs (the panel, a callback)
# applies from the next update; an abort leaves the computed steps cached and the next update resumes.
long_run = ShrinkWrap(Input=reader, NumberOfSteps=60, Resolution=64, StartingShape="Icosphere", Remeshing=0)
algorithm = long_run.GetClientSideObject()
progress = []


def edit_while_running(caller, event):
    progress.append(caller.GetProgress())
    if len(progress) == 10:
        long_run.AngleWeight = 0.6


tag = algorithm.AddObserver("ProgressEvent", edit_while_running)
long_run.UpdatePipeline(60 * tau)
algorithm.RemoveObserver(tag)
check(len(progress) >= 60 and progress[-1] == 1.0, "progress is reported every step (%d events)" % len(progress))
check(computed(long_run) == 60 and algorithm.GetOutputDataObject(0).GetNumberOfPoints() == 642,
      "a property edited during the run: the run ends with the old values")
long_run.UpdatePipeline(30 * tau)
check(computed(long_run) == 30, "and the next update starts over with the new ones (%d steps)" % computed(long_run))

long_run.AngleWeight = 0.5
tag = abort_at(algorithm, 1, after=0.3 + 0.7 * 25 / 60)  # at step 25 of the 60, after the setup
long_run.UpdatePipeline(60 * tau)
algorithm.RemoveObserver(tag)
check(algorithm.GetOutputDataObject(0).GetNumberOfPoints() == 0, "an aborted run gives an empty output")
aborted_at = computed(long_run)
long_run.UpdatePipeline(60 * tau)
check(computed(long_run) == aborted_at and algorithm.GetOutputDataObject(0).GetNumberOfPoints() == 0,
      "the same request again (a render) does not run the rest (%d steps computed)" % aborted_at)
long_run.UpdatePipeline(20 * tau)
_, data = points(long_run)
check(data.GetFieldData().GetArray("StepIndex").GetValue(0) == 20 and computed(long_run) == aborted_at,
      "another time within the %d computed steps comes from the cache" % aborted_at)
long_run.UpdatePipeline(60 * tau)
_, data = points(long_run)
check(data.GetNumberOfPoints() == 642 and data.GetFieldData().GetArray("StepIndex").GetValue(0) == 60,
      "asked for the end again, it runs to the end")

# The Offset Surface start with remeshing (the defaults), by the panel names; against the paper's
# icosphere with a fixed vertex count.
offset = ShrinkWrap(Input=reader, StartingShape="Offset Surface", StartOffsetInCells=3, GapSize=0, Remeshing=1,
                    TargetEdgeLength=0, NumberOfSteps=40)
offset.UpdatePipeline(40 * tau)
_, data = points(offset)
check(data.GetNumberOfPoints() > 642 and data.GetFieldData().GetAbstractArray("Status").GetValue(0) == "ok",
      "the Offset Surface start wraps (%d vertices)" % data.GetNumberOfPoints())
distance = data.GetPointData().GetArray("Distance")
icosphere_run = ShrinkWrap(Input=reader, NumberOfSteps=40, StartingShape="Icosphere", Remeshing=0)
icosphere_run.UpdatePipeline(40 * tau)
_, near = points(icosphere_run)
largest = lambda d: max(abs(d.GetPointData().GetArray("Distance").GetValue(i)) for i in range(d.GetNumberOfPoints()))
check(largest(data) < largest(near), "and ends closer to the target than the icosphere (largest |d| %.4f < %.4f)"
      % (largest(data), largest(near)))

finish()
