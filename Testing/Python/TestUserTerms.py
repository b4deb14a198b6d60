"""pvpython test of what issue #12 asks of the filters as a user meets them: any dataset with cells as
input (an unstructured grid gives the field and the wrap of its outer surface, equal to those of the
polygons Extract Surface makes of it), a mesh and its field selected together wired both, one name per property (panel label without spaces = Python
name = trace name), defaults a trace leaves out, the run summary equal to the figures of the
output's own arrays, and the cell sizes the panels show equal to the grids the runs use.

Usage: pvpython TestUserTerms.py <ShrinkWrap plugin .so> <mesh>
"""
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager, smtrace
from vtkmodules.util.numpy_support import vtk_to_numpy

from checks import check, finish

plugin, mesh = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, ns=globals())


def fetched(proxy):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy)


def array(data, name, cells=False):
    a = (data.GetCellData() if cells else data.GetPointData()).GetArray(name)
    return vtk_to_numpy(a) if a is not None else None


# An unstructured grid: a tetrahedral mesh's cells, and the polygons Extract Surface makes of it.
tets = Delaunay3D(Input=OpenDataFile(mesh))
surface = ExtractSurface(Input=tets)
check(fetched(tets).IsA("vtkUnstructuredGrid") and fetched(tets).GetCellType(0) == 10,
      "the input is an unstructured grid of tetrahedra")
fields = [fetched(MeshSignedDistance(Input=source, Resolution=48)) for source in (tets, surface)]
values = [array(f, "SignedDistance") for f in fields]
check(values[0] is not None and values[1] is not None and values[0].shape == values[1].shape and
      np.array_equal(values[0], values[1]) and (values[0] < 0).any(),
      "Mesh Signed Distance: the tetrahedra's field equals their extracted surface's (%d nodes, signed)"
      % len(values[0]))
wraps = [fetched(ShrinkWrap(Input=source, Resolution=48)) for source in (tets, surface)]
points = [vtk_to_numpy(w.GetPoints().GetData()) for w in wraps]
# Equal up to rounding: the two surfaces list their triangles in another order, so closest points on
# the target (the gap closing's sites come from them) can differ in the last bits.
size = np.ptp(points[1], axis=0).max() if points[1].size else 0
check(points[0].shape == points[1].shape and points[0].shape[0] > 100 and
      np.allclose(points[0], points[1], rtol=0, atol=1e-9 * size),
      "Shrink Wrap: the tetrahedra's wrap equals their extracted surface's to 1e-9 of its size (%d vertices)"
      % points[0].shape[0])

# The menu offers both filters for a dataset with cells.
for name, creator in (("Mesh Signed Distance", MeshSignedDistance), ("Shrink Wrap", ShrinkWrap)):
    proxy = creator(Input=tets)
    check(proxy.GetProperty("Input").SMProperty.IsInDomains() == 1,
          name + ": an unstructured grid is in the input's domain")
    Delete(proxy)

# The mesh and its field selected together as Shrink Wrap is created: ParaView connects both to Input,
# and the field counts as the Distance Field.
field = MeshSignedDistance(Input=surface, Resolution=48)
both = ShrinkWrap(Input=[surface, field])
check(both.GetProperty("Input").SMProperty.IsInDomains() == 1, "Shrink Wrap is offered for a mesh and its field")
together = vtk_to_numpy(fetched(both).GetPoints().GetData())
apart = vtk_to_numpy(fetched(ShrinkWrap(Input=surface, DistanceField=field)).GetPoints().GetData())
check(together.shape == apart.shape and np.array_equal(together, apart),
      "Input = [mesh, field] gives the wrap of Distance Field = field (%d vertices)" % together.shape[0])
shown = vtk_to_numpy(fetched(ShrinkWrap(Input=[surface, field], DistanceField=field)).GetPoints().GetData())
check(shown.shape == apart.shape and np.array_equal(shown, apart),
      "... and so does the field on both Input and Distance Field, as the GUI's panel shows it")
both.UpdatePropertyInformation()
check(both.GetProperty("HasDistanceField").GetData() == 1, "... and the panel hides Resolution then")

# One name per property: the panel's label without spaces and signs is the XML name is the Python name.
for creator in (MeshSignedDistance, ShrinkWrap):
    proxy = creator(Input=surface)
    names = []
    for python_name in proxy.ListProperties():
        smproperty = proxy.GetProperty(python_name).SMProperty
        xml_name = proxy.SMProxy.GetPropertyName(smproperty)
        label = smproperty.GetXMLLabel()
        if "".join(c for c in label if c.isalnum()) != python_name or xml_name != python_name:
            names.append("%s / %s / %s" % (label, xml_name, python_name))
    check(not names, "%s: panel label, XML name and Python name agree (differing: %s)"
          % (proxy.SMProxy.GetXMLLabel(), names or "none"))
    Delete(proxy)

# A trace of creating the filters at their defaults names no property, and one changed property by
# its one name.
smtrace.start_trace()
traced_field = MeshSignedDistance(Input=surface)
traced_wrap = ShrinkWrap(Input=surface, CacheMemoryMiB=100)
trace = smtrace.stop_trace()
check("OutputBounds" not in trace, "a trace of Mesh Signed Distance at its defaults records no Output Bounds")
check("CacheMemoryMiB = 100" in trace, "a trace records Cache Memory (MiB) as CacheMemoryMiB")
check(trace.count("MeshSignedDistance(") == 1 and trace.count("ShrinkWrap(") == 1,
      "the trace holds both filters (it is not empty)")

# The run summary: the figures of the output's own arrays.
wrap = wraps[1]
fd = wrap.GetFieldData()
d = np.sort(np.abs(array(wrap, "Distance")).astype(np.float64))
last = len(d) - 1
expected = [d[int(0.5 * last)], d[int(0.95 * last)], d[-1]]
given = [fd.GetArray("DistancePercentiles").GetComponent(0, k) for k in range(3)]
check(np.allclose(given, expected, rtol=0, atol=0), "summary: median, 95%% and largest |Distance| %s equal the "
      "Distance array's %s" % (given, expected))
cell = fd.GetArray("FieldCellSize").GetValue(0)
in_cells = [fd.GetArray("DistancePercentilesInCells").GetComponent(0, k) for k in range(3)]
check(cell > 0 and np.allclose(in_cells, np.array(expected) / cell, rtol=1e-12),
      "summary: the same in cells of the field (cell %.4g)" % cell)
share = float((array(wrap, "MinAngle", cells=True) < 20).mean())
check(fd.GetArray("SmallAngleShare").GetValue(0) == share,
      "summary: the share of triangles under 20 degrees equals the MinAngle array's (%.4f)" % share)
text = fd.GetAbstractArray("Summary").GetValue(0)
check(("%d vertices" % wrap.GetNumberOfPoints()) in text and "25 steps" in text and
      "0 self-intersecting" in text and fd.GetArray("SelfIntersections").GetValue(0) == 0,
      "summary line: " + text)

# One filter, one menu entry: ParaView's quick launch keeps the entries whose label holds the typed
# words, and "signed distance" or "distance" find Mesh Signed Distance, the one entry of its class.
definitions = servermanager.ProxyManager().SMProxyManager.GetProxyDefinitionManager()
entries = {}
walker = definitions.NewSingleGroupIterator("filters")
walker.InitTraversal()
while not walker.IsDoneWithTraversal():
    xml = definitions.GetProxyDefinition("filters", walker.GetProxyName())
    if xml is not None and xml.GetAttribute("class") in ("vtkMeshSignedDistance", "vtkShrinkWrapFilter"):
        entries.setdefault(xml.GetAttribute("class"), []).append(xml.GetAttribute("label"))
    walker.GoToNextItem()
check(entries == {"vtkMeshSignedDistance": ["Mesh Signed Distance"], "vtkShrinkWrapFilter": ["Shrink Wrap"]},
      "one menu entry per filter, and a search for 'signed distance' finds it (%s)" % entries)

# The cell sizes the panels show (information properties), known before a run: Mesh Signed Distance's
# grid, and the field Shrink Wrap moves on (its own or the connected one).
grid = MeshSignedDistance(Input=surface)
shown_before = grid.GridCellSize
spacing = fetched(grid).GetSpacing()[0]
check(shown_before > 0 and shown_before == spacing,
      "Grid Cell Size shows the output's spacing before the run (%.6g, spacing %.6g)" % (shown_before, spacing))
own = ShrinkWrap(Input=surface, Resolution=48)
own.UpdatePipelineInformation()
shown_before = own.FieldCellSize
moved_on = fetched(own).GetFieldData().GetArray("FieldCellSize").GetValue(0)
check(shown_before > 0 and shown_before == moved_on,
      "Field Cell Size shows the own field's cell before the run (%.6g, the run's %.6g)" % (shown_before, moved_on))
bounds = fetched(surface).GetBounds()
diagonal = float(np.linalg.norm(np.array(bounds[1::2]) - np.array(bounds[0::2])))
ran = fetched(own).GetFieldData()
check(own.ChosenGapSize == own.ChosenEdgeLength and abs(own.ChosenGapSize - diagonal / 50) < 1e-9 * diagonal and
      ran.GetArray("GapSize").GetValue(0) == own.ChosenGapSize and
      ran.GetArray("TargetEdgeLength").GetValue(0) == own.ChosenEdgeLength,
      "a mesh's Chosen Gap Size and Chosen Edge Length are the automatic diagonal / 50 (%.6g, %.6g; "
      "diagonal %.6g), before the run as in it" % (own.ChosenGapSize, own.ChosenEdgeLength, diagonal))
fixed = ShrinkWrap(Input=surface, Resolution=48, Remeshing=0, NumberOfSteps=5)
fixed.UpdatePipelineInformation()
planned, planned_gap = fixed.ChosenEdgeLength, fixed.ChosenGapSize  # the gap shows the sizes were planned
fixed_run = fetched(fixed).GetFieldData()
fixed_summary = fixed_run.GetAbstractArray("Summary").GetValue(0)
check(planned == 0 and planned_gap == own.ChosenGapSize and fixed_run.GetArray("TargetEdgeLength").GetValue(0) == 0 and
      "Remeshing off" in fixed_summary and "Target Edge Length" not in fixed_summary and
      fixed_run.GetArray("GapSize").GetValue(0) == own.ChosenGapSize,
      "with Remeshing off no edge length is used: Chosen Edge Length %.6g beside a planned Chosen Gap Size %.6g, "
      "field data 0, the summary says 'Remeshing off' (%s)"
      % (planned, planned_gap, fixed_summary[fixed_summary.find("Gap Size"):]))
reused = ShrinkWrap(Input=surface, DistanceField=grid)
reused.UpdatePipelineInformation()
check(reused.FieldCellSize == spacing and
      fetched(reused).GetFieldData().GetArray("FieldCellSize").GetValue(0) == spacing,
      "with a Distance Field, Field Cell Size is that field's spacing (%.6g)" % reused.FieldCellSize)

finish()
