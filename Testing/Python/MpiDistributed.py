"""Inputs that arrive distributed, and composite choices, under ParaView's MPI engine (issue #14).

- A mesh that arrives distributed (each rank holds every n-th triangle, whatever piece is asked for,
  as an in-situ adaptor or a script's source gives it): Mesh Signed Distance gathers it, and its
  pieces equal the serial field of the whole mesh; Shrink Wrap's surface equals the whole mesh's wrap.
- A multiblock that arrives distributed (rank r holds the blocks k with k % n == r): Shrink Wrap wraps
  each block on the rank that holds it, equal to that mesh's wrap alone.
- Mesh Signed Distance with Field Per Block on a multiblock every rank holds: each block's field is
  computed on one rank only, equal to its mesh's field alone.
- Shrink Wrap with Wrap Per Block off: one surface, on piece 0, equal to the one-process result.

Usage: mpiexec -np N pvbatch --symmetric MpiDistributed.py <ShrinkWrap plugin .so> <mesh>
"""
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData

from mpi_checks import check, finish, rank, ranks, sums

plugin, mesh_file = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())


def on_one_rank(flags):
    """How many ranks hold each of the items flagged here."""
    return [int(n) for n in sums([1 if f else 0 for f in flags])]


def values(image):
    array = image.GetPointData().GetArray("SignedDistance") if image else None
    return np.array(vtk_to_numpy(array)) if array else np.zeros(0)


def points(surface):
    return np.array(vtk_to_numpy(surface.GetPoints().GetData())) if surface and surface.GetNumberOfPoints() else np.zeros((0, 3))


def local(proxy, step=None):
    if step is None:
        proxy.UpdatePipeline()
    else:
        proxy.UpdatePipeline(step)
    return proxy.GetClientSideObject().GetOutputDataObject(0)


def whole(proxy, time=None):
    """The same filter's output in this process alone: one piece, the whole data."""
    algorithm = proxy.GetClientSideObject()
    if time is None:
        algorithm.UpdatePiece(0, 1, 0)
    else:
        algorithm.UpdateTimeStep(time, 0, 1, 0)
    return algorithm.GetOutputDataObject(0)


# Every rank's share of the triangles, whatever piece the pipeline asks for.
mesh = OpenDataFile(mesh_file)
part = ProgrammableFilter(Input=mesh, OutputDataSetType="vtkPolyData", Script="""
from paraview.modules.vtkRemotingCore import vtkProcessModule
controller = vtkProcessModule.GetProcessModule().GetGlobalController()
r, n = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
source, out = self.GetInputDataObject(0, 0), self.GetOutputDataObject(0)
out.SetPoints(source.GetPoints())
polys, ids = vtk.vtkCellArray(), vtk.vtkIdList()
for k in range(r, source.GetNumberOfCells(), n):
    source.GetCellPoints(k, ids)
    polys.InsertNextCell(ids)
out.SetPolys(polys)
""")

distance = MeshSignedDistance(Input=part, Resolution=64)
piece = vtkImageData()
piece.DeepCopy(local(distance))
held = part.GetClientSideObject().GetOutputDataObject(0).GetNumberOfCells()
serial = whole(MeshSignedDistance(Input=mesh, Resolution=64))
e, wx, wy = piece.GetExtent(), serial.GetDimensions()[0], serial.GetDimensions()[1]
diagonal = np.linalg.norm(np.array(serial.GetBounds()[1::2]) - np.array(serial.GetBounds()[0::2]))
ours = values(piece).reshape(e[5] - e[4] + 1, e[3] - e[2] + 1, e[1] - e[0] + 1) if piece.GetNumberOfPoints() else None
theirs = values(serial).reshape(-1, wy, wx)[e[4]:e[5] + 1, e[2]:e[3] + 1, e[0]:e[1] + 1]
worst = float(np.max(np.abs(ours - theirs)) / diagonal) if ours is not None else 1.0
signs = int(np.count_nonzero((ours < 0) != (theirs < 0))) if ours is not None else -1
print("rank %d of %d: holds %d of the triangles; field piece %s: largest difference %.2e of the diagonal, %d signs differ"
      % (rank, ranks, held, e, worst, signs))
check(0 < held < whole(mesh).GetNumberOfCells() and worst <= 1e-6 and signs == 0,
      "a distributed mesh: the field piece equals the serial field of the whole mesh")

settings = dict(NumberOfSteps=10, Resolution=40)
wrap = ShrinkWrap(Input=part, **settings)
ours = points(local(wrap, 10 * wrap.TimePerStep))
alone = points(whole(ShrinkWrap(Input=mesh, **settings), 10 * wrap.TimePerStep))
same = ours.shape == alone.shape and len(ours) > 0 and float(np.max(np.abs(ours - alone))) <= 1e-9 * diagonal
check(same if rank == 0 else len(ours) == 0,
      "a distributed mesh: Shrink Wrap's surface (piece 0) equals the whole mesh's wrap (%d points, %d alone)"
      % (len(ours), len(alone)))

# A multiblock whose blocks arrive distributed, and the same blocks whole on every rank.
blocks_script = """
from paraview.modules.vtkRemotingCore import vtkProcessModule
from vtkmodules.vtkFiltersSources import vtkSphereSource
controller = vtkProcessModule.GetProcessModule().GetGlobalController()
r, n = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
out = self.GetOutputDataObject(0)
for k in range(4):
    made = vtkSphereSource()
    made.SetCenter(3 * k, 0, 0)
    made.SetRadius(0.6 + 0.1 * k)
    made.SetThetaResolution(20)
    made.SetPhiResolution(20)
    made.Update()
    out.SetBlock(k, made.GetOutput() if not DISTRIBUTED or k % n == r else None)
"""
distributed = ProgrammableSource(OutputDataSetType="vtkMultiblockDataSet", Script=blocks_script.replace("DISTRIBUTED", "True"))
whole_blocks = ProgrammableSource(OutputDataSetType="vtkMultiblockDataSet", Script=blocks_script.replace("DISTRIBUTED", "False"))

wraps = local(ShrinkWrap(Input=distributed, **settings), 10 * wrap.TimePerStep)
reference = whole(ShrinkWrap(Input=whole_blocks, **settings), 10 * wrap.TimePerStep)
here = []
for k in range(4):
    ours, alone = points(wraps.GetBlock(k)), points(reference.GetBlock(k))
    mine = k % ranks == rank
    good = (ours.shape == alone.shape and len(ours) > 0 and np.array_equal(ours, alone)) if mine else len(ours) == 0
    check(good, "a distributed multiblock: block %d %s (%d points)" % (k, "wrapped here, as alone" if mine else "left to its rank", len(ours)))
    here.append(len(ours) > 0)
check(on_one_rank(here) == [1, 1, 1, 1], "a distributed multiblock: every block wrapped once, where it is")

# A field per block, the blocks shared out among the ranks.
per_block = MeshSignedDistance(Input=whole_blocks, Resolution=32, FieldPerBlock=1)
fields = local(per_block)
reference = whole(MeshSignedDistance(Input=whole_blocks, Resolution=32, FieldPerBlock=1))
here = []
for k in range(4):
    ours, alone = values(fields.GetBlock(k)), values(reference.GetBlock(k))
    if len(ours):
        check(len(alone) > 0 and np.array_equal(ours, alone), "Field Per Block: block %d's field equals its field alone" % k)
    here.append(len(ours) > 0)
check(on_one_rank(here) == [1, 1, 1, 1], "Field Per Block: every block's field computed on one rank")

# All blocks wrapped together: one surface, on piece 0.
together = ShrinkWrap(Input=whole_blocks, WrapPerBlock=0, **settings)
ours = points(local(together, 10 * wrap.TimePerStep))
alone = points(whole(together, 10 * wrap.TimePerStep))
check(isinstance(together.GetClientSideObject().GetOutputDataObject(0), vtkPolyData) and
      ((len(ours) > 0 and np.array_equal(ours, alone)) if rank == 0 else len(ours) == 0),
      "Wrap Per Block off: one surface on piece 0 (%d points)" % len(ours))

finish()
