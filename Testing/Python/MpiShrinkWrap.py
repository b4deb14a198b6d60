"""Shrink Wrap under ParaView's MPI engine: piece 0 holds the surface, the other ranks' pieces are
empty, so the gathered data has the surface once.

Usage: mpiexec -np 2 pvbatch --symmetric MpiShrinkWrap.py <ShrinkWrap plugin .so> <mesh>
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingCore import vtkProcessModule

plugin, mesh = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())
controller = vtkProcessModule.GetProcessModule().GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()

wrap = ShrinkWrap(Input=OpenDataFile(mesh), NumberOfSteps=20, Resolution=48, SubdivisionLevel=3,
                  StartingShape="Icosphere", Remeshing=0)
wrap.UpdatePipeline(20 * wrap.TimeStep)
local = wrap.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()
total = wrap.GetDataInformation().GetNumberOfPoints()
expected_local = 642 if rank == 0 else 0
ok = local == expected_local and (rank != 0 or total == 642) and ranks == 2
print("rank %d of %d: %d points here, %d in all: %s" % (rank, ranks, local, total, "ok" if ok else "FAIL"))
if not ok:
    sys.exit(1)  # (a normal end lets pvbatch finalize MPI)
