"""What a finished wrap keeps: resident memory after Shrink Wrap's update and after deleting it.

  pvpython retained_memory.py ShrinkWrap.so mesh.obj SUBDIVISIONS

The mesh, triangulated and Loop-subdivided SUBDIVISIONS times (3: 64 times the triangles), wrapped
at the defaults to its last step.
"""
import gc
import resource
import sys
import time

from paraview.simple import *  # noqa: F403 (ShrinkWrap comes with the plugin)

LoadPlugin(sys.argv[1], remote=False, ns=globals())


def resident_mb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024


target = Triangulate(Input=OpenDataFile(sys.argv[2]))
if int(sys.argv[3]) > 0:
    target = LoopSubdivision(Input=target, NumberofSubdivisions=int(sys.argv[3]))
target.UpdatePipeline()
print("target: %d triangles, resident %.0f MB" % (target.GetDataInformation().GetNumberOfCells(), resident_mb()))
wrap = ShrinkWrap(Input=target)
start = time.time()
wrap.UpdatePipeline(1e9)
print("wrapped in %.1f s: resident %.0f MB (peak %.0f MB)" % (
    time.time() - start, resident_mb(), resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024))
Delete(wrap)
del wrap
gc.collect()
print("after deleting the filter: resident %.0f MB" % resident_mb())
