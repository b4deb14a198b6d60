"""Mesh Signed Distance as pvpython runs it, on issue 62's equal grid.

  pvpython msd_pipeline.py ShrinkWrap.so mesh.obj [RESOLUTION=240] [SCALE=1.5] [RUNS=3]

The grid: a cube of RESOLUTION cells a side around the mesh's bounds scaled SCALE about their
centre (Use Explicit Grid), the same grid as `BenchSignedDistance <mesh> --cube SCALE`. Prints, for
each run, the seconds of UpdatePipeline (a property changed before each, so each computes) and of
the data information ParaView gathers after it, and the process's peak resident growth against the
output array.
"""
import resource
import sys
import time

from paraview.simple import *  # noqa: F403 (MeshSignedDistance comes with the plugin)

LoadPlugin(sys.argv[1], remote=False, ns=globals())
resolution = int(sys.argv[3]) if len(sys.argv) > 3 else 240
scale = float(sys.argv[4]) if len(sys.argv) > 4 else 1.5
runs = int(sys.argv[5]) if len(sys.argv) > 5 else 3


def peak_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


mesh = OpenDataFile(sys.argv[2])
mesh.UpdatePipeline()
b = mesh.GetDataInformation().GetBounds()
half = scale * max(b[1] - b[0], b[3] - b[2], b[5] - b[4]) / 2
centre = [(b[2 * a] + b[2 * a + 1]) / 2 for a in range(3)]
bounds = []
for c in centre:
    bounds += [c - half, c + half]
field = MeshSignedDistance(Input=mesh, UseExplicitGrid=1, OutputBounds=bounds,
                           OutputDimensions=[resolution + 1] * 3)
before = peak_mb()
output_mb = (resolution + 1) ** 3 * 4 / 2**20
times = []
for run in range(runs):
    field.BoxScale = 1.1 + 0.01 * (run % 2)  # unused by an explicit grid, but a change: a new update
    start = time.perf_counter()
    field.UpdatePipeline()
    updated = time.perf_counter()
    info = field.GetDataInformation().GetNumberOfPoints()
    gathered = time.perf_counter()
    times.append(updated - start)
    print("run %d: update %.3f s, data information %.3f s (%d nodes)" % (
        run + 1, updated - start, gathered - updated, info))
print("fastest update: %.3f s; peak resident growth %.0f MB = %.2f x the output array (%.0f MB)" % (
    min(times), peak_mb() - before, (peak_mb() - before) / output_mb, output_mb))
