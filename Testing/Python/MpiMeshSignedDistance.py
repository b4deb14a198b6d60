"""Mesh Signed Distance under ParaView's MPI engine (issue #14): every rank computes its share of the
grid's planes, the ranks hand each other the parts of their pieces, and each piece equals the serial
field at its nodes (1e-6 of the diagonal, the same signs); the pieces cover the grid; ghost layers
are marked; a Contour at 0 of the distributed field has the serial contour's points.

Usage: mpiexec -np N pvbatch --symmetric MpiMeshSignedDistance.py <ShrinkWrap plugin .so> <resolution> <mesh>...
"""
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData, vtkContourFilter

from mpi_checks import check, controller, finish, rank, ranks, sums

plugin, resolution, meshes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
LoadPlugin(plugin, ns=globals())
def contour_points(pieces):
    """Points of the contours of all pieces, merged where pieces meet (rank 0; -1 elsewhere)."""
    if rank != 0:
        controller.Send(pieces, 0, 77)
        return -1
    append = vtkAppendPolyData()
    append.AddInputData(pieces)
    for r in range(1, ranks):
        other = vtkPolyData()
        controller.Receive(other, r, 77)
        append.AddInputData(other)
    clean = vtkCleanPolyData()
    clean.SetInputConnection(append.GetOutputPort())
    clean.SetTolerance(0)
    clean.Update()
    return clean.GetOutput().GetNumberOfPoints()


for mesh in meshes:
    name = mesh.split("/")[-1]
    distance = MeshSignedDistance(Input=OpenDataFile(mesh), Resolution=resolution)
    contour = Contour(Input=distance, ContourBy=["POINTS", "SignedDistance"], Isosurfaces=[0.0])
    contour.UpdatePipeline()  # asks the field for a piece per rank, with a ghost layer
    piece = vtkImageData()
    piece.DeepCopy(distance.GetClientSideObject().GetOutputDataObject(0))
    contour_piece = vtkPolyData()
    contour_piece.DeepCopy(contour.GetClientSideObject().GetOutputDataObject(0))

    # The serial field of the same filter, on this rank alone: one piece, the whole grid.
    algorithm = distance.GetClientSideObject()
    algorithm.UpdatePiece(0, 1, 0)
    whole = vtkImageData()
    whole.DeepCopy(algorithm.GetOutputDataObject(0))
    wx, wy, wz = whole.GetDimensions()
    diagonal = np.linalg.norm(np.array(whole.GetBounds()[1::2]) - np.array(whole.GetBounds()[0::2]))
    serial_values = vtk_to_numpy(whole.GetPointData().GetArray("SignedDistance")).reshape(wz, wy, wx)

    def compare(piece, what):
        e = piece.GetExtent()
        nodes = piece.GetNumberOfPoints()
        ours = vtk_to_numpy(piece.GetPointData().GetArray("SignedDistance")).reshape(
            e[5] - e[4] + 1, e[3] - e[2] + 1, e[1] - e[0] + 1) if nodes else np.zeros((0, 0, 0))
        serial = serial_values[e[4]:e[5] + 1, e[2]:e[3] + 1, e[0]:e[1] + 1]
        worst = float(np.max(np.abs(ours - serial)) / diagonal) if nodes else 0.0
        signs = int(np.count_nonzero((ours < 0) != (serial < 0)))
        print("rank %d of %d: %s %s %s, %d nodes of %d: largest difference %.2e of the diagonal, %d signs differ"
              % (rank, ranks, name, what, e, nodes, wx * wy * wz, worst, signs))
        check(nodes > 0 and worst <= 1e-6 and signs == 0, name + " " + what + " equals the serial field")
        return nodes

    nodes = compare(piece, "piece")
    status = piece.GetFieldData().GetAbstractArray("DistanceStatus")
    check(status is not None and status.GetValue(0) == whole.GetFieldData().GetAbstractArray("DistanceStatus").GetValue(0),
          name + " piece has the serial field's status")
    ghosts = piece.GetPointData().GetArray("vtkGhostType")
    check(ghosts is not None and vtk_to_numpy(ghosts).any(), name + " piece marks its ghost layer")
    # The pieces cover the grid (pieces share their border planes, ghost layers overlap more).
    check(sums([nodes])[0] >= wx * wy * wz, name + " pieces cover the grid")

    serial_contour = vtkContourFilter()
    serial_contour.SetInputData(whole)
    serial_contour.SetValue(0, 0.0)
    serial_contour.Update()
    merged = contour_points(contour_piece)
    if rank == 0:
        expected = serial_contour.GetOutput().GetNumberOfPoints()
        print("rank 0 of %d: %s contour at 0: %d points from the pieces, %d serial" % (ranks, name, merged, expected))
        check(expected > 0 and abs(merged - expected) <= 0.001 * expected, name + " contour of the pieces equals the serial one")

    # Pieces of another shape than the slabs the filter asks for (a consumer asking for part of the
    # x range; the pipeline splits that in z): the ranks compute even shares of planes and hand each
    # other the parts.
    block = [rank * wx // ranks, (rank + 1) * wx // ranks - 1, 0, wy - 1, 0, wz - 1]
    algorithm.UpdatePiece(rank, ranks, 0, block)
    block_piece = algorithm.GetOutputDataObject(0)
    e = block_piece.GetExtent()
    check(e[0] == block[0] and e[1] == block[1], name + " block piece has the x range asked for")
    compare(block_piece, "block piece")
    Delete(contour)
    Delete(distance)

finish()
