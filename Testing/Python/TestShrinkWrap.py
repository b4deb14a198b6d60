"""pvpython test of Shrink Wrap's time awareness, as the ParaView animation uses it.

Usage: pvpython TestShrinkWrap.py <ShrinkWrap plugin .so> <mesh>
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin, mesh = sys.argv[1], sys.argv[2]
checks, failures = [], []


def check(condition, message):
    checks.append(message)
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


def computed(proxy):
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty("NumberOfComputedSteps").GetData()


def points(proxy):
    data = servermanager.Fetch(proxy)
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())], data


LoadPlugin(plugin, ns=globals())
reader = OpenDataFile(mesh)
wrap = ShrinkWrap(Input=reader, NumberOfSteps=40, Resolution=64)
tau = wrap.TimeStep
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

wrap.C = 2.0
wrap.UpdatePipeline(5 * tau)
check(computed(wrap) == 5, "changing C drops the cache (5 steps computed again)")

print("%d passed, %d failed" % (len(checks) - len(failures), len(failures)))
sys.exit(1 if failures else 0)
