"""Helpers of the MPI tests (pvbatch --symmetric): each rank's checks, printed as
'rank r of n: what: ok|FAIL' (ctest reads rank 0's lines), and sums over the ranks."""
import sys

from paraview.modules.vtkRemotingCore import vtkProcessModule
from vtkmodules.vtkCommonCore import vtkDoubleArray

controller = vtkProcessModule.GetProcessModule().GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
_failures = []


def check(ok, what):
    print("rank %d of %d: %s: %s" % (rank, ranks, what, "ok" if ok else "FAIL"))
    if not ok:
        _failures.append(what)


def sums(values):
    """Each value summed over the ranks (every rank gets the sums)."""
    mine, out = vtkDoubleArray(), vtkDoubleArray()
    for v in values:
        mine.InsertNextValue(v)
    controller.AllReduce(mine, out, 2)  # vtkCommunicator::SUM_OP
    return [out.GetValue(k) for k in range(len(values))]


def finish():
    if _failures:
        sys.exit(1)  # (a normal end lets pvbatch finalize MPI)
