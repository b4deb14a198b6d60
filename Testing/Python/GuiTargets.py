"""Writes the files the first-Apply GUI test opens, as a user has them: CGAL's open elephant
(elephant-with-holes.off, which ParaView 5.11 cannot read) as elephant-with-holes.obj, and the
vertices of CGAL's bunny00.obj as a point cloud, bunny-points.vtp (one vertex cell per point).
GuiTargets.py <CGAL data/meshes folder> <output folder>"""
import os
import sys

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

meshes, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)


def off_to_obj(source, target):
    words = open(source).read().split()
    assert words[0] == "OFF", source
    nv, nf = int(words[1]), int(words[2])
    at = 4
    with open(target, "w") as obj:
        for _ in range(nv):
            obj.write("v %s %s %s\n" % tuple(words[at:at + 3]))
            at += 3
        for _ in range(nf):
            n = int(words[at])
            obj.write("f %s\n" % " ".join(str(int(i) + 1) for i in words[at + 1:at + 1 + n]))
            at += 1 + n


def obj_vertices_to_cloud(source, target):
    points = vtkPoints()
    for line in open(source):
        if line.startswith("v "):
            points.InsertNextPoint(*map(float, line.split()[1:4]))
    verts = vtkCellArray()
    for i in range(points.GetNumberOfPoints()):
        verts.InsertNextCell(1)
        verts.InsertCellPoint(i)
    cloud = vtkPolyData()
    cloud.SetPoints(points)
    cloud.SetVerts(verts)
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(target)
    writer.SetInputData(cloud)
    # Inline binary: Debian 12's ParaView with libexpat1 2.5.0-1+deb12u2 cannot read the default
    # raw appended data back (the XML parser stops at it).
    writer.SetDataModeToBinary()
    assert writer.Write() == 1, target


off_to_obj(os.path.join(meshes, "elephant-with-holes.off"), os.path.join(out, "elephant-with-holes.obj"))
obj_vertices_to_cloud(os.path.join(meshes, "bunny00.obj"), os.path.join(out, "bunny-points.vtp"))
print("wrote elephant-with-holes.obj and bunny-points.vtp to", out)
