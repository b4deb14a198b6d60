"""A fine wrap's setup and steps as pvpython runs it (issue 62's diag/N sizes).

  pvpython fine_setup.py ShrinkWrap.so mesh.obj N [RESOLUTION=1.5 N] [RUNS=2]

Shrink Wrap with Target Edge Length = Gap Size = diagonal / N and Resolution 1.5 N (the benchmark's
sizes): the seconds until its first step is shown (the fields, the gap closing and the start), and
until its last, fastest of RUNS (a new filter each), with the process's peak resident memory.
"""
import math
import resource
import sys
import time

from paraview.simple import *  # noqa: F403 (ShrinkWrap comes with the plugin)

LoadPlugin(sys.argv[1], remote=False, ns=globals())
n = float(sys.argv[3])
resolution = int(sys.argv[4]) if len(sys.argv) > 4 else int(round(1.5 * n))
runs = int(sys.argv[5]) if len(sys.argv) > 5 else 2
target = Triangulate(Input=OpenDataFile(sys.argv[2]))
target.UpdatePipeline()
b = target.GetDataInformation().GetBounds()
diagonal = math.sqrt(sum((b[2 * a + 1] - b[2 * a]) ** 2 for a in range(3)))
best = None
for run in range(runs):
    wrap = ShrinkWrap(Input=target, TargetEdgeLength=diagonal / n, GapSize=diagonal / n,
                      Resolution=resolution)
    start = time.perf_counter()
    wrap.UpdatePipeline(0)
    first = time.perf_counter() - start
    wrap.UpdatePipeline(1e9)
    total = time.perf_counter() - start
    vertices = wrap.GetDataInformation().GetNumberOfPoints()
    print("run %d: start %.2f s, all steps %.2f s, %d vertices" % (run + 1, first, total, vertices))
    best = (first, total) if best is None or total < best[1] else best
    Delete(wrap)
print("fastest: start %.2f s, total %.2f s; peak resident %.0f MB" % (
    best[0], best[1], resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024))
