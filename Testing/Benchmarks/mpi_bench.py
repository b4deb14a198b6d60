"""The filters under ParaView's MPI engine (issue #14), one Markdown table row per run: wall time of
the update (slowest rank) and peak memory per rank.

Usage: [mpiexec -np R] pvbatch [--symmetric] mpi_bench.py distance <plugin .so> <label> <N> <mesh .vtk>
         Mesh Signed Distance on N^3 nodes around the mesh
       [mpiexec -np R] pvbatch [--symmetric] mpi_bench.py wrap <plugin .so> <label> <mesh .vtk>...
         Shrink Wrap at its defaults on a multiblock of the meshes, to its last step
       pvpython mpi_bench.py convert <mesh .off> <mesh .vtk>   (ParaView 5.11 reads no OFF)
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


if sys.argv[1] == "convert":
    writer = vtkPolyDataWriter()
    writer.SetFileName(sys.argv[3])
    writer.SetInputData(read_off(sys.argv[2]))
    writer.SetFileTypeToBinary()
    writer.Write()
    sys.exit(0)

mode, plugin, label = sys.argv[1], sys.argv[2], sys.argv[3]
LoadPlugin(plugin, ns=globals())
controller = vtkProcessModule.GetProcessModule().GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
if mode == "distance":
    nodes, path = int(sys.argv[4]), sys.argv[5]
    source = OpenDataFile(path)
    bounds_reader = vtkPolyDataReader()  # the whole mesh's bounds on every rank (a piece's are its own)
    bounds_reader.SetFileName(path)
    bounds_reader.Update()
    b = bounds_reader.GetOutput().GetBounds()
    del bounds_reader
    pad = [0.05 * (b[2 * a + 1] - b[2 * a]) for a in range(3)]
    algorithm = MeshSignedDistance(Input=source, UseExplicitGrid=1, OutputDimensions=[nodes] * 3,
                                   OutputBounds=[b[0] - pad[0], b[1] + pad[0], b[2] - pad[1], b[3] + pad[1],
                                                 b[4] - pad[2], b[5] + pad[2]])
    update = algorithm.UpdatePipeline
else:
    algorithm = ShrinkWrap(Input=GroupDatasets(Input=[OpenDataFile(path) for path in sys.argv[4:]]))
    update = lambda: algorithm.UpdatePipeline(algorithm.TimestepValues[-1])  # noqa: E731
algorithm.UpdatePipelineInformation()


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


def size(data):
    return data.GetNumberOfPoints() if data.IsA("vtkDataSet") else sum(
        data.GetBlock(k).GetNumberOfPoints() for k in range(data.GetNumberOfBlocks()) if data.GetBlock(k))


before = status_kib("VmRSS")
controller.Barrier()
start = time.perf_counter()
update()
seconds = largest(time.perf_counter() - start)
peak = largest(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0)
added = largest((status_kib("VmHWM") - before) / 1024.0)
smallest_piece = -largest(-float(size(algorithm.GetClientSideObject().GetOutputDataObject(0))))
if rank == 0:
    print("| %s | %d | %.2f | %.0f | %.0f | %d |" % (label, ranks, seconds, peak, added, smallest_piece))
