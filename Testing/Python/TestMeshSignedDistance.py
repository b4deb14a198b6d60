"""pvpython/pvbatch test: the built plugin loaded as a user would, Mesh Signed Distance run on a reader.

Usage: pvpython TestMeshSignedDistance.py <ShrinkWrap plugin .so> <Data/trefoil.obj>
"""
import math
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

from checks import check, finish

plugin, mesh = sys.argv[1], sys.argv[2]



LoadPlugin(plugin, ns=globals())
check("MeshSignedDistance" in globals(), "LoadPlugin(path, ns=globals()) defines MeshSignedDistance")

# The proxy as the property panel shows it: defaults from the paper, the Shrink Wrap menu category.
prototype = servermanager.ProxyManager().GetPrototypeProxy("filters", "MeshSignedDistance")
hints = prototype.GetHints()
menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
check(menu is not None and menu.GetAttribute("category") == "Shrink Wrap", "listed under Filters > Shrink Wrap")

reader = OpenDataFile(mesh)
sdf = MeshSignedDistance(Input=reader)
check(sdf.Resolution == 120 and abs(sdf.BoxScale - 1.1) < 1e-12 and sdf.OffsetFactor == 0.15,
      "defaults: Resolution 120, BoxScale 1.1 (phi), OffsetFactor 0.15")
sdf.Resolution = 96
sdf.UpdatePipeline()
image = servermanager.Fetch(sdf)
dims = image.GetDimensions()
spacing = image.GetSpacing()
values = image.GetPointData().GetArray("SignedDistance")
check(max(dims) == 97, "96 cells along the longest axis: dimensions %s" % (dims,))
check(spacing[0] == spacing[1] == spacing[2], "equal spacing %s" % (spacing,))
check(values is not None and values.GetDataTypeAsString() == "float", "float point array SignedDistance")
check(image.GetFieldData().GetArray("Signed").GetValue(0) == 1, "the closed knot gives a signed field")
low, high = values.GetRange()
check(-0.36 < low < -0.3, "deepest inside value is about minus the tube radius 0.35: %.4f" % low)

# A node far outside: its value is its distance to the mesh, checked against the mesh's points.
points = servermanager.Fetch(reader).GetPoints()
corner = image.GetPoint(0)
nearest = min(math.dist(corner, points.GetPoint(i)) for i in range(points.GetNumberOfPoints()))
check(abs(values.GetValue(0) - nearest) < 0.05 * nearest,
      "corner value %.4f matches the distance to the mesh (%.4f, vertex bound)" % (values.GetValue(0), nearest))

# Downstream filters work on the output as on any image.
contour = Contour(Input=sdf, ContourBy=["POINTS", "SignedDistance"], Isosurfaces=[0.0])
contour.UpdatePipeline()
contour_points = contour.GetDataInformation().GetNumberOfPoints()
check(contour_points > 1000, "the zero contour is a surface (%d points)" % contour_points)

# Bad parameters: an error and an empty output, and the session goes on.
sdf.Resolution = 0
sdf.UpdatePipeline()
check(sdf.GetDataInformation().GetNumberOfPoints() == 0, "Resolution 0 gives an empty output")
sdf.Resolution = 32
sdf.UpdatePipeline()
check(sdf.GetDataInformation().GetNumberOfPoints() > 0, "the filter recovers with a valid Resolution")

finish()
