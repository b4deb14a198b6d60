"""Shrink Wrap under ParaView's MPI engine: piece 0 holds the surface, the other ranks' pieces are
empty, so the gathered data has the surface once. A multiblock target (issue #14): every block is
wrapped on one rank only, in parallel, and equals its wrap in one process. The target's data carried
onto the wrap and the target as measured (issue #64) equal one process's. A series is followed
frame by frame (issue #63): every rank goes from frame to frame with the others, piece 0 holds the
wrap of the frame asked for.

Usage: mpiexec -np 2 pvbatch --symmetric MpiShrinkWrap.py <ShrinkWrap plugin .so> <mesh>
"""
import os
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403

from mpi_checks import check, controller, finish, rank, ranks, sums
from series import torus, write_series

plugin, mesh = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())

wrap = ShrinkWrap(Input=OpenDataFile(mesh), NumberOfSteps=20, Resolution=48, SubdivisionLevel=3,
                  StartingShape="Icosphere", Remeshing=0)
wrap.UpdatePipeline(20 * wrap.TimePerStep)
local = wrap.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()
total = wrap.GetDataInformation().GetNumberOfPoints()
expected_local = 642 if rank == 0 else 0
check(local == expected_local and (rank != 0 or total == 642) and ranks == 2,
      "%d points here, %d in all" % (local, total))

# Four blocks, shared out among the ranks; the reference: the same filter in this process alone.
blocks = GroupDatasets(Input=[OpenDataFile(mesh)] + [
    Sphere(Center=[3 * k, 0, 0], Radius=0.5 + 0.2 * k, ThetaResolution=24, PhiResolution=24) for k in range(1, 4)])
settings = dict(NumberOfSteps=10, Resolution=40)
wrap_blocks = ShrinkWrap(Input=blocks, **settings)
wrap_blocks.UpdatePipeline(10 * wrap_blocks.TimePerStep)
mine = wrap_blocks.GetClientSideObject().GetOutputDataObject(0)
reference = ShrinkWrap(Input=blocks, **settings).GetClientSideObject()
reference.UpdatePiece(0, 1, 0)  # in this process only: every block
whole = reference.GetOutputDataObject(0)
wrapped_here = []
for k in range(4):
    ours, alone = mine.GetBlock(k), whole.GetBlock(k)
    here = ours.GetNumberOfPoints() > 0
    same = ours.GetNumberOfPoints() == alone.GetNumberOfPoints() and all(
        ours.GetPoint(i) == alone.GetPoint(i) for i in range(ours.GetNumberOfPoints()))
    check(same if here else alone.GetNumberOfPoints() > 0,
          "block %d %s (%d points)" % (k, "wrapped here" if here else "left to another rank", ours.GetNumberOfPoints()))
    wrapped_here.append(1 if here else 0)
check(sums(wrapped_here) == [1, 1, 1, 1] and 0 < sum(wrapped_here) < 4, "every block wrapped on one rank, some here")

# The target's data on the wrap and the target as measured (issue #64): a point field computed on the
# mesh, read where the ranks hold it, gathered and carried onto the wrap on piece 0 as in one process.
field = Calculator(Input=OpenDataFile(mesh), ResultArrayName="p", Function="coordsX^2+3*coordsY")
carried = ShrinkWrap(Input=field, **settings)
carried.UpdatePipeline(10 * carried.TimePerStep)
ours = carried.GetClientSideObject().GetOutputDataObject(0)
ours_measured = carried.GetClientSideObject().GetOutputDataObject(1)
alone = ShrinkWrap(Input=field, **settings).GetClientSideObject()
alone.UpdatePiece(0, 1, 0)  # in this process only
reference, reference_measured = alone.GetOutputDataObject(0), alone.GetOutputDataObject(1)


def values(data, name):
    array = data.GetPointData().GetArray(name)
    return [array.GetTuple1(i) for i in range(array.GetNumberOfTuples())] if array else None


if rank == 0:
    check(ours.GetNumberOfPoints() > 0 and values(ours, "p") == values(reference, "p"),
          "p on the wrap equals the wrap's in one process (%d points)" % ours.GetNumberOfPoints())
    check(ours_measured.GetNumberOfPoints() == reference_measured.GetNumberOfPoints() and
          sorted(values(ours_measured, "DistanceToWrap") or [0]) ==
          sorted(values(reference_measured, "DistanceToWrap") or [1]),
          "DistanceToWrap equals the one process's (%d target points)" % ours_measured.GetNumberOfPoints())
else:
    check(ours.GetNumberOfPoints() == 0 and ours_measured.GetNumberOfPoints() == 0,
          "the other pieces are empty on both ports")
per_block = ShrinkWrap(Input=GroupDatasets(Input=[field, Sphere(Center=[3, 0, 0])]), **settings)
per_block.UpdatePipeline(10 * per_block.TimePerStep)
mine, measured = per_block.GetClientSideObject().GetOutputDataObject(0), \
    per_block.GetClientSideObject().GetOutputDataObject(1)
here = [k for k in range(2) if mine.GetBlock(k).GetNumberOfPoints() > 0]
check(all(measured.GetBlock(k).GetPointData().GetArray("DistanceToWrap") is not None for k in here) and
      all(mine.GetBlock(k).GetPointData().GetArray("p") is not None for k in here if k == 0) and
      sums([len(here)]) == [2],
      "per block, each rank measures the blocks it wraps (%s here)" % here)
# A series of four frames of a torus moving along x by 0.2 a frame, written by rank 0.
folder = os.path.join(tempfile.gettempdir(), "shrinkwrap_mpi_series")
if rank == 0:
    os.makedirs(folder, exist_ok=True)
    write_series(folder, "torus", torus(0.4, 48, 24), [0, 1, 2, 3], lambda p, k: (p[0] + 0.2 * k, p[1], p[2]))
controller.Barrier()
follow = ShrinkWrap(Input=OpenDataFile(os.path.join(folder, "torus.pvd")), Resolution=48)
xs = []
for t in (0, 3):
    follow.UpdatePipeline(t)
    data = follow.GetClientSideObject().GetOutputDataObject(0)
    xs.append(data.GetBounds()[0] if data.GetNumberOfPoints() > 0 else None)
if rank == 0:
    check(None not in xs and abs(xs[1] - xs[0] - 0.6) < 0.01,
          "a followed series: frame 3's wrap stands 0.6 further along x (%s)" % xs)
else:
    check(xs == [None, None], "a followed series: the other pieces are empty")
finish()
