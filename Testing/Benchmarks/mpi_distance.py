"""Mesh Signed Distance on N^3 nodes under ParaView's MPI engine (issue #14): wall time of the update
(slowest rank) and peak memory per rank, as one Markdown table row.

Usage: [mpiexec -np R] pvbatch [--symmetric] mpi_distance.py <ShrinkWrap plugin .so> <mesh .vtk> <N> <label>
       pvpython mpi_distance.py --convert <mesh .off> <mesh .vtk>   (ParaView 5.11 reads no OFF)
Threads per rank: VTK_SMP_MAX_THREADS (unset: all cores).
"""
import resource
import sys
import time

from paraview.simple import *  # noqa: F401,F403
from paraview.modules.vtkRemotingCore import vtkProcessModule
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOLegacy import vtkPolyDataReader, vtkPolyDataWriter



def read_off(name):
    """ParaView 5.11 reads no OFF: vertices and faces into a vtkPolyData."""
    words = [w for line in open(name) for w in line.split("#")[0].split()]
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    points, cells, at = vtkPoints(), vtkCellArray(), 4
    for _ in range(nv):
        points.InsertNextPoint(float(words[at]), float(words[at + 1]), float(words[at + 2]))
        at += 3
    for _ in range(nf):
        n = int(words[at])
        cells.InsertNextCell(n)
        for v in words[at + 1:at + 1 + n]:
            cells.InsertCellPoint(int(v))
        at += 1 + n
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(cells)
    return mesh


if sys.argv[1] == "--convert":
    writer = vtkPolyDataWriter()
    writer.SetFileName(sys.argv[3])
    writer.SetInputData(read_off(sys.argv[2]))
    writer.SetFileTypeToBinary()
    writer.Write()
    sys.exit(0)

plugin, path, nodes, label = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
LoadPlugin(plugin, ns=globals())
controller = vtkProcessModule.GetProcessModule().GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
source = OpenDataFile(path)
bounds_reader = vtkPolyDataReader()  # the whole mesh's bounds on every rank (a piece's are its own)
bounds_reader.SetFileName(path)
bounds_reader.Update()
b = bounds_reader.GetOutput().GetBounds()
del bounds_reader
pad = [0.05 * (b[2 * a + 1] - b[2 * a]) for a in range(3)]
distance = MeshSignedDistance(Input=source, UseExplicitGrid=1, OutputDimensions=[nodes] * 3,
                              OutputBounds=[b[0] - pad[0], b[1] + pad[0], b[2] - pad[1], b[3] + pad[1],
                                            b[4] - pad[2], b[5] + pad[2]])
distance.UpdatePipelineInformation()


def status_kib(key):
    for line in open("/proc/self/status"):
        if line.startswith(key + ":"):
            return int(line.split()[1])
    return 0


def largest(value):
    mine, out = vtkDoubleArray(), vtkDoubleArray()
    mine.InsertNextValue(value)
    controller.AllReduce(mine, out, 0)  # vtkCommunicator::MAX_OP
    return out.GetValue(0)


before = status_kib("VmRSS")
controller.Barrier()
start = time.perf_counter()
distance.UpdatePipeline()
seconds = largest(time.perf_counter() - start)
peak = largest(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0)
added = largest((status_kib("VmHWM") - before) / 1024.0)
local = distance.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints()
smallest_piece = -largest(-float(local))
if rank == 0:
    print("| %s | %d | %.2f | %.0f | %.0f | %d |" % (label, ranks, seconds, peak, added, smallest_piece))
